#include "core/optimal/interior_point.h"

#include "core/optimal/reduced_kkt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace bladeaxis::optimal {

namespace {

using Eigen::VectorXd;
using Sparse = Eigen::SparseMatrix<double>;

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

double largestMagnitude(const Sparse& matrix) {
    double largest = 0.0;
    for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
        for (Sparse::InnerIterator it(matrix, col); it; ++it) {
            largest = std::max(largest, std::abs(it.value()));
        }
    }
    return largest;
}

double largestMagnitude(const VectorXd& v) {
    return v.size() > 0 ? v.cwiseAbs().maxCoeff() : 0.0;
}

// Each row divided by its largest |coefficient| (right-hand side too): the solution is the same,
// and the normal matrix no longer mixes 1 and 1e4 scales.
void equilibrateRows(Sparse& matrix, VectorXd& rhs) {
    VectorXd largest = VectorXd::Zero(matrix.rows());
    for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
        for (Sparse::InnerIterator it(matrix, col); it; ++it) {
            largest[it.row()] = std::max(largest[it.row()], std::abs(it.value()));
        }
    }
    const VectorXd inverse =
        largest.unaryExpr([](double value) { return value > 0.0 ? 1.0 / value : 1.0; });
    matrix = inverse.asDiagonal() * matrix;
    rhs = rhs.cwiseProduct(inverse);
}

// The problem with unit-scale rows; the minimiser x is unchanged. The objective keeps its
// scale: the duality gap is measured relative to it, so the caller gives it a natural one.
ConvexProgram equilibrated(const ConvexProgram& problem) {
    ConvexProgram scaled = problem;
    const auto n = problem.c.size();
    if (scaled.P.rows() == 0) {
        scaled.P.resize(n, n);
    }
    equilibrateRows(scaled.A, scaled.b);
    equilibrateRows(scaled.E, scaled.d);
    return scaled;
}

struct Direction {
    VectorXd dx, dy, ds, dz;
};

class InteriorPoint {
  public:
    explicit InteriorPoint(const ConvexProgram& problem)
        : m_p(problem), m_quadratic(largestMagnitude(problem.P) > 0.0), m_kkt(problem) {
        const auto n = problem.c.size(), m = problem.A.rows(), p = problem.E.rows();
        m_x = VectorXd::Zero(n);
        m_y = VectorXd::Zero(p);
        m_s = (problem.b - problem.A * m_x).cwiseMax(1.0);
        m_z = VectorXd::Ones(m);
        m_rhs.resize(n + p);
    }

    Result<InteriorPointSolution> run(double tolerance, double acceptable, int maxIterations) {
        InteriorPointSolution solution;
        const double primalScale = 1.0 + std::max(largestMagnitude(m_p.b), largestMagnitude(m_p.d));
        VectorXd bestX = m_x;
        double bestResidual = std::numeric_limits<double>::infinity();
        for (int k = 1; k <= maxIterations; ++k) {
            solution.iterations = k;
            const VectorXd curvature = m_p.P * m_x;
            const VectorXd inequalityForce = m_p.A.transpose() * m_z;
            const VectorXd equalityForce = m_p.E.transpose() * m_y;
            const VectorXd rDual = curvature + m_p.c + inequalityForce + equalityForce;
            const VectorXd rPrimal = m_p.A * m_x + m_s - m_p.b;
            const VectorXd rEquality = m_p.E * m_x - m_p.d;
            // Relative to the terms that cancel in them (as OSQP measures): a Hessian of 1e10
            // (second differences of 0.1 mm chords) leaves round-off of 1e-5 in P x alone.
            const double dualScale =
                1.0 + std::max({largestMagnitude(curvature), largestMagnitude(inequalityForce),
                                largestMagnitude(equalityForce), largestMagnitude(m_p.c)});
            const double gap = m_s.dot(m_z);
            const double mu = gap / static_cast<double>(m_s.size());
            const double objective = m_p.c.dot(m_x) + 0.5 * m_x.dot(curvature);
            const double residual = std::max(
                {largestMagnitude(rDual) / dualScale,
                 std::max(largestMagnitude(rPrimal), largestMagnitude(rEquality)) / primalScale,
                 gap / (1.0 + std::abs(objective))});
            if (residual < bestResidual) {
                bestResidual = residual;
                bestX = m_x;
            }
            if (residual < tolerance) {
                solution.converged = true;
                break;
            }
            if (!std::isfinite(residual) || !factorise()) {
                break;
            }
            step(rDual, rPrimal, rEquality, mu);
        }
        // Near a degenerate vertex the weights z/s of the normal equations span some 40 orders
        // of magnitude, and a Hessian of second differences has a condition number growing
        // like n^4: the LU's round-off then keeps the residual from its last digits and the
        // iterates wander around the optimum. The best iterate is taken when it met
        // `acceptable` (1e-6 by default, spec §10.1's KKT bound; far below what the figures
        // resolve).
        if (!solution.converged && bestResidual < acceptable) {
            solution.converged = true;
            m_x = bestX;
        }
        if (!solution.converged) {
            char best[32];
            std::snprintf(best, sizeof best, "%.1e", bestResidual);
            return makeError(ErrorCode::Infeasible, "interior point: no convergence in " +
                                                        std::to_string(solution.iterations) +
                                                        " iterations (best relative residual " +
                                                        best +
                                                        "; infeasible or unbounded problem?)");
        }
        solution.relativeResidual = bestResidual;
        solution.x = m_x;
        return solution;
    }

  private:
    // Predictor (affine scaling), then Mehrotra's centring and second-order correction. A QP
    // takes one step length for primal and dual (its dual residual depends on x).
    void step(const VectorXd& rDual, const VectorXd& rPrimal, const VectorXd& rEquality,
              double mu) {
        m_complement = -m_s.cwiseProduct(m_z);
        solve(rDual, rPrimal, rEquality, m_complement, m_affine);
        const double primalStep = stepToBoundary(m_s, m_affine.ds);
        const double dualStep = stepToBoundary(m_z, m_affine.dz);
        const double muAffine = (m_s + primalStep * m_affine.ds).dot(m_z + dualStep * m_affine.dz) /
                                static_cast<double>(m_s.size());
        const double sigma = std::pow(muAffine / mu, 3);
        m_complement -= m_affine.ds.cwiseProduct(m_affine.dz);
        m_complement.array() += sigma * mu;
        solve(rDual, rPrimal, rEquality, m_complement, m_corrected);
        const Direction& d = m_corrected;
        double alphaPrimal = stepToBoundary(m_s, d.ds);
        double alphaDual = stepToBoundary(m_z, d.dz);
        if (m_quadratic) {
            alphaPrimal = alphaDual = std::min(alphaPrimal, alphaDual);
        }
        m_x += alphaPrimal * d.dx;
        m_s += alphaPrimal * d.ds;
        m_y += alphaDual * d.dy;
        m_z += alphaDual * d.dz;
    }

    // The reduced KKT matrix at W = Z S^-1 (see reduced_kkt.h).
    bool factorise() {
        m_weights = m_z.cwiseQuotient(m_s);
        return m_kkt.factorise(m_weights);
    }

    // Into `d`, with no allocation once the vectors have their sizes.
    void solve(const VectorXd& rDual, const VectorXd& rPrimal, const VectorXd& rEquality,
               const VectorXd& complement, Direction& d) {
        const auto n = m_x.size(), p = m_y.size();
        // dz = S^-1 (complement + Z rPrimal + Z A dx), ds = -rPrimal - A dx.
        m_base = (complement + m_z.cwiseProduct(rPrimal)).cwiseQuotient(m_s);
        // Products inside a sum are accumulated into the sum term by term by Eigen; the
        // iterates' last bits depend on that order, so these stay single expressions.
        m_rhs.head(n) = -rDual - m_p.A.transpose() * m_base;
        m_rhs.tail(p) = -rEquality;
        m_kkt.solve(m_rhs, m_solution);
        d.dx = m_solution.head(n);
        d.dy = m_solution.tail(p);
        d.ds = -rPrimal - m_p.A * d.dx;
        m_rowsTimesDx.noalias() = m_p.A * d.dx;
        d.dz = m_base + m_z.cwiseProduct(m_rowsTimesDx).cwiseQuotient(m_s);
    }

    const ConvexProgram& m_p;
    bool m_quadratic;
    ReducedKkt m_kkt;
    VectorXd m_x, m_y, m_s, m_z;
    // Work vectors of the Newton steps, kept across iterations.
    VectorXd m_weights, m_complement, m_base, m_rhs, m_solution, m_rowsTimesDx;
    Direction m_affine, m_corrected;
};

bool sizesMatch(const ConvexProgram& problem) {
    const auto n = problem.c.size();
    const bool quadraticFits =
        problem.P.rows() == 0 || (problem.P.rows() == n && problem.P.cols() == n);
    return quadraticFits && problem.A.cols() == n && problem.b.size() == problem.A.rows() &&
           (problem.E.rows() == 0 || problem.E.cols() == n) &&
           problem.d.size() == problem.E.rows() && problem.A.rows() > 0;
}

} // namespace

Result<InteriorPointSolution> solveInteriorPoint(const ConvexProgram& problem,
                                                 const InteriorPointSettings& settings) {
    if (!sizesMatch(problem)) {
        return makeError(ErrorCode::InvalidArgument, "QP/LP sizes do not match");
    }
    const ConvexProgram scaled = equilibrated(problem);
    auto solution =
        InteriorPoint(scaled).run(settings.tolerance, settings.acceptable, settings.maxIterations);
    if (solution) {
        const VectorXd& x = solution->x;
        solution->objective =
            problem.c.dot(x) + (problem.P.rows() > 0 ? 0.5 * x.dot(problem.P * x) : 0.0);
    }
    return solution;
}

} // namespace bladeaxis::optimal
