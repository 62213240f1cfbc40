#include "core/optimal/reduced_kkt.h"

#include <algorithm>

namespace bladeaxis::optimal {

namespace {

using Eigen::Index;
using Sparse = Eigen::SparseMatrix<double>;
using RowMajorSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Free variables that no inequality touches keep the matrix regular; the equality block's is
// kept below the round-off of the variables' one.
constexpr double variableRegularisation = 1e-12;
constexpr double equalityRegularisation = -1e-14;

} // namespace

ReducedKkt::ReducedKkt(const ConvexProgram& problem)
    : m_variables(problem.c.size()), m_equalities(problem.E.rows()) {
    buildPattern(problem);
    collectTerms(problem);
}

// Every entry any iteration has: P, A'A, E, E' and the diagonal.
void ReducedKkt::buildPattern(const ConvexProgram& problem) {
    const Index n = m_variables, size = m_variables + m_equalities;
    std::vector<Eigen::Triplet<double>> entries;
    for (Index i = 0; i < size; ++i) {
        entries.emplace_back(i, i, 0.0);
    }
    for (Index col = 0; col < problem.P.outerSize(); ++col) {
        for (Sparse::InnerIterator it(problem.P, col); it; ++it) {
            entries.emplace_back(it.row(), it.col(), 0.0);
        }
    }
    const RowMajorSparse rows = problem.A;
    for (Index r = 0; r < rows.outerSize(); ++r) {
        for (RowMajorSparse::InnerIterator a(rows, r); a; ++a) {
            for (RowMajorSparse::InnerIterator b(rows, r); b; ++b) {
                entries.emplace_back(a.col(), b.col(), 0.0);
            }
        }
    }
    for (Index col = 0; col < problem.E.outerSize(); ++col) {
        for (Sparse::InnerIterator it(problem.E, col); it; ++it) {
            entries.emplace_back(n + it.row(), it.col(), 0.0);
            entries.emplace_back(it.col(), n + it.row(), 0.0);
        }
    }
    m_matrix.resize(size, size);
    m_matrix.setFromTriplets(entries.begin(), entries.end());
    m_matrix.makeCompressed();
}

// The index of entry (row, col) in the compressed matrix's values.
Index ReducedKkt::slot(Index row, Index col) const {
    const Index begin = m_matrix.outerIndexPtr()[col], end = m_matrix.outerIndexPtr()[col + 1];
    const int* const rows = m_matrix.innerIndexPtr();
    return std::lower_bound(rows + begin, rows + end, row) - rows;
}

void ReducedKkt::collectTerms(const ConvexProgram& problem) {
    const Index n = m_variables;
    // Entry (i, j) of A'WA sums (A(r,i) w_r) A(r,j) over the rows r in order, as Eigen's
    // product of A'W and A does.
    const RowMajorSparse rows = problem.A;
    for (Index r = 0; r < rows.outerSize(); ++r) {
        m_weightedRowBegin.push_back(m_weighted.size());
        for (RowMajorSparse::InnerIterator a(rows, r); a; ++a) {
            for (RowMajorSparse::InnerIterator b(rows, r); b; ++b) {
                m_weighted.push_back({slot(a.col(), b.col()), a.value(), b.value()});
            }
        }
    }
    m_weightedRowBegin.push_back(m_weighted.size());
    for (Index col = 0; col < problem.P.outerSize(); ++col) {
        for (Sparse::InnerIterator it(problem.P, col); it; ++it) {
            m_fixed.push_back({slot(it.row(), it.col()), it.value()});
        }
    }
    for (Index col = 0; col < problem.E.outerSize(); ++col) {
        for (Sparse::InnerIterator it(problem.E, col); it; ++it) {
            m_fixed.push_back({slot(n + it.row(), it.col()), it.value()});
            m_fixed.push_back({slot(it.col(), n + it.row()), it.value()});
        }
    }
    for (Index i = 0; i < n; ++i) {
        m_fixed.push_back({slot(i, i), variableRegularisation});
    }
    for (Index i = 0; i < m_equalities; ++i) {
        m_fixed.push_back({slot(n + i, n + i), equalityRegularisation});
    }
}

bool ReducedKkt::factorise(const Eigen::VectorXd& weights) {
    double* const values = m_matrix.valuePtr();
    std::fill(values, values + m_matrix.nonZeros(), 0.0);
    for (Index r = 0; r < weights.size(); ++r) {
        const auto row = static_cast<std::size_t>(r);
        for (std::size_t k = m_weightedRowBegin[row]; k < m_weightedRowBegin[row + 1]; ++k) {
            const WeightedTerm& term = m_weighted[k];
            values[term.slot] += (term.left * weights[r]) * term.right;
        }
    }
    for (const FixedTerm& term : m_fixed) {
        values[term.slot] += term.value;
    }
    if (!m_patternAnalysed) {
        m_lu.analyzePattern(m_matrix);
        m_patternAnalysed = true;
    }
    m_lu.factorize(m_matrix);
    return m_lu.info() == Eigen::Success;
}

void ReducedKkt::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) const {
    solution = m_lu.solve(rhs);
}

} // namespace bladeaxis::optimal
