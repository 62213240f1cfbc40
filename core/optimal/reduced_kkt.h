#pragma once
// The matrix of each Newton step of the interior point (interior_point.h), with the slacks and
// inequality multipliers eliminated:
//   [P + A'WA + delta I, E'; E, -epsilon I],  W = diag(weights) (Z S^-1 of the iterate),
// regularised slightly for free variables that no inequality touches. Its pattern is the same
// at every iteration, so the sparse LU's ordering (COLAMD) and symbolic analysis are done once,
// and each iteration only writes the values into the fixed pattern (every product of A'WA
// knows where it goes) and factorises them.
//
// The values are summed in the order Eigen's products and sums take (A'WA row by row of A,
// then P, then the regularisation), so a factorisation is the one a matrix built from those
// products would get, bit for bit. The LU pivots by rows (partial pivoting) after a
// fill-reducing column ordering: the degenerate vertices need it, where the weights span some
// 40 orders of magnitude.

#include "core/optimal/interior_point.h"

#include <Eigen/SparseLU>

#include <vector>

namespace bladeaxis::optimal {

class ReducedKkt {
  public:
    // For the problem's sizes and patterns (P n x n, possibly without entries; E may have no
    // rows); its values are copied.
    explicit ReducedKkt(const ConvexProgram& problem);

    // One weight per row of A; false where the LU fails (a singular matrix).
    bool factorise(const Eigen::VectorXd& weights);

    // [dx; dy] = K^-1 rhs (size n + p), with the last successful factorisation.
    void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) const;

  private:
    // A term (left * weight) * right of A'WA, the product's own rounding.
    struct WeightedTerm {
        Eigen::Index slot;
        double left, right;
    };
    // A value of P, E or the regularisation.
    struct FixedTerm {
        Eigen::Index slot;
        double value;
    };

    void buildPattern(const ConvexProgram& problem);
    Eigen::Index slot(Eigen::Index row, Eigen::Index col) const;
    void collectTerms(const ConvexProgram& problem);

    Eigen::Index m_variables = 0, m_equalities = 0;
    Eigen::SparseMatrix<double> m_matrix; // compressed, the pattern of every iteration
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> m_lu;
    bool m_patternAnalysed = false;
    std::vector<WeightedTerm> m_weighted;        // row by row of A
    std::vector<std::size_t> m_weightedRowBegin; // of each row of A in m_weighted, and the end
    std::vector<FixedTerm> m_fixed;              // P, then the regularisation and E, E'
};

} // namespace bladeaxis::optimal
