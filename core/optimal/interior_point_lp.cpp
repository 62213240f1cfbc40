#include "core/optimal/interior_point_lp.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace bladeaxis::optimal {

namespace {

using Eigen::VectorXd;
using Sparse = Eigen::SparseMatrix<double>;

constexpr double kStalledToleranceFactor = 100.0;

// The largest step in [0, 1] keeping v + step * dv > 0, shortened by 1 % from the boundary.
double stepToBoundary(const VectorXd& v, const VectorXd& dv) {
    double step = 1.0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        if (dv[i] < 0.0) {
            step = std::min(step, -0.99 * v[i] / dv[i]);
        }
    }
    return step;
}

struct Direction {
    VectorXd dx, dy, ds, dz;
};

class InteriorPoint {
  public:
    explicit InteriorPoint(const SparseLp& lp) : m_lp(lp) {
        const auto n = lp.c.size(), m = lp.A.rows(), p = lp.E.rows();
        m_x = VectorXd::Zero(n);
        m_y = VectorXd::Zero(p);
        m_s = (lp.b - lp.A * m_x).cwiseMax(1.0);
        m_z = VectorXd::Ones(m);
    }

    Result<LpSolution> run(double tolerance, int maxIterations) {
        LpSolution solution;
        const double scale =
            1.0 + std::max({m_lp.b.cwiseAbs().maxCoeff(), m_lp.c.cwiseAbs().maxCoeff(),
                            m_lp.E.rows() ? m_lp.d.cwiseAbs().maxCoeff() : 0.0});
        VectorXd bestX = m_x;
        double bestResidual = std::numeric_limits<double>::infinity();
        for (int k = 1; k <= maxIterations; ++k) {
            solution.iterations = k;
            const VectorXd rDual = m_lp.c + m_lp.A.transpose() * m_z + m_lp.E.transpose() * m_y;
            const VectorXd rPrimal = m_lp.A * m_x + m_s - m_lp.b;
            const VectorXd rEquality = m_lp.E * m_x - m_lp.d;
            const double mu = m_s.dot(m_z) / static_cast<double>(m_s.size());
            const double residual =
                std::max({rDual.lpNorm<Eigen::Infinity>(), rPrimal.lpNorm<Eigen::Infinity>(),
                          m_lp.E.rows() ? rEquality.lpNorm<Eigen::Infinity>() : 0.0, mu}) /
                scale;
            if (residual < bestResidual) {
                bestResidual = residual;
                bestX = m_x;
            }
            if (residual < tolerance) {
                solution.converged = true;
                break;
            }
            if (!factorise()) {
                return makeError(ErrorCode::Infeasible, "interior point: singular system");
            }
            // Predictor (affine scaling), then Mehrotra's centring and second-order correction.
            const VectorXd complement = -m_s.cwiseProduct(m_z);
            const Direction affine = solve(rDual, rPrimal, rEquality, complement);
            const double primalStep = stepToBoundary(m_s, affine.ds);
            const double dualStep = stepToBoundary(m_z, affine.dz);
            const double muAffine = (m_s + primalStep * affine.ds).dot(m_z + dualStep * affine.dz) /
                                    static_cast<double>(m_s.size());
            const double sigma = std::pow(muAffine / mu, 3);
            const VectorXd corrected = complement - affine.ds.cwiseProduct(affine.dz) +
                                       VectorXd::Constant(m_s.size(), sigma * mu);
            const Direction step = solve(rDual, rPrimal, rEquality, corrected);
            const double alphaPrimal = stepToBoundary(m_s, step.ds);
            const double alphaDual = stepToBoundary(m_z, step.dz);
            m_x += alphaPrimal * step.dx;
            m_s += alphaPrimal * step.ds;
            m_y += alphaDual * step.dy;
            m_z += alphaDual * step.dz;
        }
        // Near a degenerate vertex the weights z/s of the normal equations span some 40 orders
        // of magnitude and the LU's round-off keeps the dual residual from its last digits: the
        // iterates then wander around the optimum. The best iterate is taken when it met a
        // tolerance 100x the requested one (still far below what the gap figures resolve).
        if (!solution.converged && bestResidual < kStalledToleranceFactor * tolerance) {
            solution.converged = true;
            m_x = bestX;
        }
        if (!solution.converged) {
            return makeError(ErrorCode::Infeasible,
                             "interior point: no convergence in " + std::to_string(maxIterations) +
                                 " iterations (best relative residual " +
                                 std::to_string(bestResidual) + "; infeasible or unbounded LP?)");
        }
        solution.relativeResidual = bestResidual;
        solution.x = m_x;
        solution.objective = m_lp.c.dot(m_x);
        return solution;
    }

  private:
    // KKT of the reduced system: [A' D A, E'; E, 0] with D = Z S^-1, a tiny regularisation for
    // free variables that no inequality touches.
    bool factorise() {
        const auto n = m_x.size(), p = m_y.size();
        const VectorXd weights = m_z.cwiseQuotient(m_s);
        const Sparse normal = m_lp.A.transpose() * weights.asDiagonal() * m_lp.A;
        std::vector<Eigen::Triplet<double>> triplets;
        for (Eigen::Index col = 0; col < normal.outerSize(); ++col) {
            for (Sparse::InnerIterator it(normal, col); it; ++it) {
                triplets.emplace_back(it.row(), it.col(), it.value());
            }
        }
        for (Eigen::Index col = 0; col < m_lp.E.outerSize(); ++col) {
            for (Sparse::InnerIterator it(m_lp.E, col); it; ++it) {
                triplets.emplace_back(n + it.row(), it.col(), it.value());
                triplets.emplace_back(it.col(), n + it.row(), it.value());
            }
        }
        for (Eigen::Index i = 0; i < n; ++i) {
            triplets.emplace_back(i, i, 1e-12);
        }
        for (Eigen::Index i = 0; i < p; ++i) {
            triplets.emplace_back(n + i, n + i, -1e-14);
        }
        Sparse kkt(n + p, n + p);
        kkt.setFromTriplets(triplets.begin(), triplets.end());
        m_lu.compute(kkt);
        return m_lu.info() == Eigen::Success;
    }

    Direction solve(const VectorXd& rDual, const VectorXd& rPrimal, const VectorXd& rEquality,
                    const VectorXd& complement) const {
        const auto n = m_x.size(), p = m_y.size();
        // dz = S^-1 (complement + Z rPrimal + Z A dx), ds = -rPrimal - A dx.
        const VectorXd base = (complement + m_z.cwiseProduct(rPrimal)).cwiseQuotient(m_s);
        VectorXd rhs(n + p);
        rhs.head(n) = -rDual - m_lp.A.transpose() * base;
        rhs.tail(p) = -rEquality;
        const VectorXd solution = m_lu.solve(rhs);
        Direction d;
        d.dx = solution.head(n);
        d.dy = solution.tail(p);
        d.ds = -rPrimal - m_lp.A * d.dx;
        d.dz = base + m_z.cwiseProduct(m_lp.A * d.dx).cwiseQuotient(m_s);
        return d;
    }

    const SparseLp& m_lp;
    VectorXd m_x, m_y, m_s, m_z;
    Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> m_lu;
};

} // namespace

Result<LpSolution> solveLp(const SparseLp& lp, double tolerance, int maxIterations) {
    const auto n = lp.c.size();
    if (lp.A.cols() != n || lp.b.size() != lp.A.rows() || (lp.E.rows() > 0 && lp.E.cols() != n) ||
        lp.d.size() != lp.E.rows() || lp.A.rows() == 0) {
        return makeError(ErrorCode::InvalidArgument, "LP sizes do not match");
    }
    return InteriorPoint(lp).run(tolerance, maxIterations);
}

} // namespace bladeaxis::optimal
