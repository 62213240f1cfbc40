#pragma once
// A primal-dual interior-point method (Mehrotra predictor-corrector) for the convex QPs and LPs
// of the physical-limit baseline (spec §9):
//   min 1/2 x'Px + c'x  s.t.  A x <= b,  E x = d,   x free   (P = 0 or empty: an LP).
// Both objectives of a layer (`optimal-qp`, the smoothest, and `optimal-lp`, the minimum peak)
// are solved here. Spec §9.3 sketches an ADMM; a first-order method stalls at 1e-5..1e-6 on
// layers of a real program (900-1900 samples, chords from 15 um to 1 mm) and cannot reach an
// LP's vertex, while each Newton step here costs one factorisation of the banded normal
// matrix P + A'WA (half-bandwidth 2; the LP's epigraph variable adds one dense row and column,
// which the fill-reducing ordering puts last), so a layer takes 20-60 factorisations of O(n).
// Rows are equilibrated to unit infinity norm and the objective to unit scale before solving:
// a second difference over a 15 um chord has coefficients 1e4 times those of a bound row.

#include "core/base/error.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace bladeaxis::optimal {

struct ConvexProgram {
    Eigen::SparseMatrix<double> P; // n x n symmetric positive semi-definite, or 0 x 0 (an LP)
    Eigen::VectorXd c;
    Eigen::SparseMatrix<double> A; // inequality rows, finite right-hand sides
    Eigen::VectorXd b;
    Eigen::SparseMatrix<double> E; // equality rows (may have 0 rows)
    Eigen::VectorXd d;
};

struct InteriorPointSolution {
    Eigen::VectorXd x;
    double objective = 0.0; // 1/2 x'Px + c'x in the problem's own scale
    int iterations = 0;
    bool converged = false;
    double relativeResidual = 0.0; // max of the scaled primal, dual and gap residuals
};

struct InteriorPointSettings {
    double tolerance = 1e-9;  // relative KKT residual that ends the iterations
    double acceptable = 1e-6; // best residual accepted when round-off stalls the iterates
    int maxIterations = 200;
};

// Converged means a relative KKT residual below `tolerance`, or, where the iterates stall at
// round-off near a degenerate optimum, a best iterate below `acceptable`.
// Errors: InvalidArgument (sizes), Infeasible (no convergence within the iteration limit, as
// for an infeasible or unbounded problem; the message gives the best residual reached).
Result<InteriorPointSolution> solveInteriorPoint(const ConvexProgram& problem,
                                                 const InteriorPointSettings& settings = {});

} // namespace bladeaxis::optimal
