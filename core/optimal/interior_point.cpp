#include "core/optimal/interior_point.h"

#include <Eigen/SparseLU>

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
        : m_p(problem), m_quadratic(largestMagnitude(problem.P) > 0.0) {
        const auto n = problem.c.size(), m = problem.A.rows(), p = problem.E.rows();
        m_x = VectorXd::Zero(n);
        m_y = VectorXd::Zero(p);
        m_s = (problem.b - problem.A * m_x).cwiseMax(1.0);
        m_z = VectorXd::Ones(m);
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
        const VectorXd complement = -m_s.cwiseProduct(m_z);
        const Direction affine = solve(rDual, rPrimal, rEquality, complement);
        const double primalStep = stepToBoundary(m_s, affine.ds);
        const double dualStep = stepToBoundary(m_z, affine.dz);
        const double muAffine = (m_s + primalStep * affine.ds).dot(m_z + dualStep * affine.dz) /
                                static_cast<double>(m_s.size());
        const double sigma = std::pow(muAffine / mu, 3);
        const VectorXd corrected = complement - affine.ds.cwiseProduct(affine.dz) +
                                   VectorXd::Constant(m_s.size(), sigma * mu);
        const Direction d = solve(rDual, rPrimal, rEquality, corrected);
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

    // KKT of the reduced system: [P + A' W A, E'; E, 0] with W = Z S^-1, a tiny regularisation
    // for free variables that no inequality touches.
    bool factorise() {
        const auto n = m_x.size(), p = m_y.size();
        const VectorXd weights = m_z.cwiseQuotient(m_s);
        const Sparse normal = Sparse(m_p.A.transpose() * weights.asDiagonal() * m_p.A) + m_p.P;
        std::vector<Eigen::Triplet<double>> triplets;
        for (Eigen::Index col = 0; col < normal.outerSize(); ++col) {
            for (Sparse::InnerIterator it(normal, col); it; ++it) {
                triplets.emplace_back(it.row(), it.col(), it.value());
            }
        }
        for (Eigen::Index col = 0; col < m_p.E.outerSize(); ++col) {
            for (Sparse::InnerIterator it(m_p.E, col); it; ++it) {
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
        rhs.head(n) = -rDual - m_p.A.transpose() * base;
        rhs.tail(p) = -rEquality;
        const VectorXd solution = m_lu.solve(rhs);
        Direction d;
        d.dx = solution.head(n);
        d.dy = solution.tail(p);
        d.ds = -rPrimal - m_p.A * d.dx;
        d.dz = base + m_z.cwiseProduct(m_p.A * d.dx).cwiseQuotient(m_s);
        return d;
    }

    const ConvexProgram& m_p;
    bool m_quadratic;
    VectorXd m_x, m_y, m_s, m_z;
    Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> m_lu;
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
