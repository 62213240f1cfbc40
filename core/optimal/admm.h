#pragma once
// An OSQP-style ADMM for convex QPs  min 1/2 x'Px + q'x  s.t.  l <= Mx <= u  (spec §9.3), on
// Eigen sparse matrices: one LDL' factorisation of P + sigma I + M' diag(rho) M per rho, equality
// rows (l = u) with a 1000x larger rho as in OSQP, over-relaxation alpha, and adaptive rho.
// Written here because no QP solver of this kind is packaged in Debian 12 (spec §9.2).

#include "core/base/error.h"

#include <Eigen/Sparse>

#include <vector>

namespace bladeaxis::optimal {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Vector = Eigen::VectorXd;

struct QpProblem {
    SparseMatrix P;      // n x n, symmetric positive semi-definite (both triangles stored)
    Vector q;            // n
    SparseMatrix M;      // m x n
    Vector lower, upper; // m; +-infinity allowed
};

struct AdmmSettings {
    double rho = 0.1, sigma = 1e-6, alpha = 1.6;
    double epsAbsolute = 1e-7, epsRelative = 1e-7;
    int maxIterations = 50000;
    int rhoUpdateInterval = 50;
};

struct QpSolution {
    Vector x, y; // primal solution, constraint multipliers
    double objective = 0.0;
    double primalResidual = 0.0, dualResidual = 0.0;
    int iterations = 0;
    bool converged = false;
};

// Errors: InvalidArgument (sizes, l > u), Internal (the KKT matrix cannot be factorised).
// A run that hits maxIterations is returned with converged = false.
Result<QpSolution> solveQp(const QpProblem& problem, const AdmmSettings& settings = {});

} // namespace bladeaxis::optimal
