#pragma once
// A dense primal-dual interior-point method (Mehrotra predictor-corrector) for small LPs
//   min c'x  s.t.  A x <= b,  E x = d,   x free,
// used for the min-peak baseline of spec §9 (`optimal-lp`), where the ADMM of admm.h stalls: an
// LP has no curvature, and first-order methods approach its vertex too slowly for a reference.
// The matrices are sparse (the normal equations of a layer are banded but for the epigraph
// variable), factorised by a sparse LU each iteration.

#include "core/base/error.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace bladeaxis::optimal {

struct SparseLp {
    Eigen::VectorXd c;
    Eigen::SparseMatrix<double> A; // inequality rows
    Eigen::VectorXd b;
    Eigen::SparseMatrix<double> E; // equality rows (may have 0 rows)
    Eigen::VectorXd d;
};

struct LpSolution {
    Eigen::VectorXd x;
    double objective = 0.0;
    int iterations = 0;
    bool converged = false;
    double relativeResidual = 0.0; // max KKT residual / problem scale of the returned point
};

// Converged means a relative KKT residual below `tolerance`, or, where the iterates stall at
// round-off near a degenerate optimum, a best iterate below 100 x `tolerance`.
// Errors: InvalidArgument (sizes), Infeasible (no convergence within the iteration limit, as
// for an infeasible or unbounded problem).
Result<LpSolution> solveLp(const SparseLp& lp, double tolerance = 1e-9, int maxIterations = 200);

} // namespace bladeaxis::optimal
