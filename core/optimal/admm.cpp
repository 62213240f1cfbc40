#include "core/optimal/admm.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace bladeaxis::optimal {

namespace {

double infinityNorm(const Vector& v) {
    return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff();
}

Status validate(const QpProblem& p) {
    const auto n = p.P.rows();
    if (p.P.cols() != n || p.q.size() != n || p.M.cols() != n || p.lower.size() != p.M.rows() ||
        p.upper.size() != p.M.rows()) {
        return makeError(ErrorCode::InvalidArgument, "QP sizes do not match");
    }
    for (Eigen::Index i = 0; i < p.lower.size(); ++i) {
        if (std::isnan(p.lower[i]) || std::isnan(p.upper[i]) || p.lower[i] > p.upper[i]) {
            return makeError(ErrorCode::InvalidArgument,
                             "QP constraint " + std::to_string(i) + " has lower > upper or NaN");
        }
    }
    return {};
}

class Admm {
  public:
    Admm(const QpProblem& problem, const AdmmSettings& settings)
        : m_p(problem), m_s(settings), m_rho(problem.M.rows()), m_Mt(problem.M.transpose()) {
        setRho(settings.rho);
    }

    Result<QpSolution> run() {
        const auto n = m_p.P.rows(), m = m_p.M.rows();
        Vector x = Vector::Zero(n), z = Vector::Zero(m), y = Vector::Zero(m);
        if (!factorise()) {
            return makeError(ErrorCode::Internal, "the ADMM system could not be factorised");
        }
        QpSolution solution;
        for (int k = 1; k <= m_s.maxIterations; ++k) {
            const Vector rhs = m_s.sigma * x - m_p.q + m_Mt * (m_rho.cwiseProduct(z) - y);
            const Vector xTilde = m_ldlt.solve(rhs);
            const Vector zTilde = m_p.M * xTilde;
            x = m_s.alpha * xTilde + (1.0 - m_s.alpha) * x;
            const Vector zRelaxed = m_s.alpha * zTilde + (1.0 - m_s.alpha) * z;
            const Vector zNext =
                (zRelaxed + y.cwiseQuotient(m_rho)).cwiseMax(m_p.lower).cwiseMin(m_p.upper);
            y += m_rho.cwiseProduct(zRelaxed - zNext);
            z = zNext;
            solution.iterations = k;
            if (k % 10 == 0 || k == m_s.maxIterations) {
                if (converged(x, z, y, solution)) {
                    solution.converged = true;
                    break;
                }
                if (k % m_s.rhoUpdateInterval == 0 && adaptRho(x, z, y) && !factorise()) {
                    return makeError(ErrorCode::Internal,
                                     "the ADMM system could not be refactorised");
                }
            }
        }
        solution.x = x;
        solution.y = y;
        solution.objective = 0.5 * x.dot(m_p.P * x) + m_p.q.dot(x);
        return solution;
    }

  private:
    void setRho(double rho) {
        m_rhoScalar = rho;
        for (Eigen::Index i = 0; i < m_rho.size(); ++i) {
            const bool equality = m_p.upper[i] - m_p.lower[i] < 1e-12;
            m_rho[i] = equality ? 1e3 * rho : rho;
        }
    }

    bool factorise() {
        const auto n = m_p.P.rows();
        SparseMatrix identity(n, n);
        identity.setIdentity();
        SparseMatrix K = m_p.P + m_s.sigma * identity + m_Mt * m_rho.asDiagonal() * m_p.M;
        m_ldlt.compute(K);
        return m_ldlt.info() == Eigen::Success;
    }

    struct Scales {
        double primal, dual;
    };

    Scales residuals(const Vector& x, const Vector& z, const Vector& y, QpSolution& s) const {
        const Vector Mx = m_p.M * x, Px = m_p.P * x, Mty = m_Mt * y;
        s.primalResidual = infinityNorm(Mx - z);
        s.dualResidual = infinityNorm(Px + m_p.q + Mty);
        return {std::max(infinityNorm(Mx), infinityNorm(z)),
                std::max({infinityNorm(Px), infinityNorm(Mty), infinityNorm(m_p.q)})};
    }

    bool converged(const Vector& x, const Vector& z, const Vector& y, QpSolution& s) const {
        const Scales scale = residuals(x, z, y, s);
        return s.primalResidual <= m_s.epsAbsolute + m_s.epsRelative * scale.primal &&
               s.dualResidual <= m_s.epsAbsolute + m_s.epsRelative * scale.dual;
    }

    // OSQP's rule: balance the relative primal and dual residuals; refactor on a 5x change.
    bool adaptRho(const Vector& x, const Vector& z, const Vector& y) {
        QpSolution s;
        const Scales scale = residuals(x, z, y, s);
        const double primal = s.primalResidual / std::max(scale.primal, 1e-30);
        const double dual = s.dualResidual / std::max(scale.dual, 1e-30);
        const double rho =
            std::clamp(m_rhoScalar * std::sqrt(primal / std::max(dual, 1e-30)), 1e-6, 1e6);
        if (rho > 5.0 * m_rhoScalar || rho < 0.2 * m_rhoScalar) {
            setRho(rho);
            return true;
        }
        return false;
    }

    const QpProblem& m_p;
    const AdmmSettings& m_s;
    Vector m_rho;
    double m_rhoScalar = 0.1;
    SparseMatrix m_Mt;
    Eigen::SimplicialLDLT<SparseMatrix> m_ldlt;
};

} // namespace

Result<QpSolution> solveQp(const QpProblem& problem, const AdmmSettings& settings) {
    if (auto status = validate(problem); !status) {
        return std::unexpected(status.error());
    }
    return Admm(problem, settings).run();
}

} // namespace bladeaxis::optimal
