// Why the optimum uses its own interior point rather than the solvers Debian packages (spec
// §9.2): the same layer problem (optimal::minimumPeakProgram, optimal::smoothestProgram) solved
// by ours, by GLPK's simplex and interior point (LP), and by ALGLIB's sparse interior point
// (QP). The layer is a middle layer of a 40-revolution finishing pass (867 samples, NACA 4418
// blade, 1.5 um chordal tolerance), the size of the programs the optimum has to solve. Each
// benchmark reports the optimum it found (`objective`), so agreement is visible beside time.

#include "core/blade/presets.h"
#include "core/optimal/layer_optimum.h"
#include "core/scheduling/schedule.h"
#include "tests/support/real_size_pass.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <glpk.h>
#include <libalglib/optimization.h>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace bladeaxis;
using Sparse = Eigen::SparseMatrix<double>;

optimal::LayerBounds realSizeLayer() {
    blade::BladeSpec bladeSpec = blade::demoBladeSpec();
    bladeSpec.profile = blade::NacaProfile{0.04, 0.40, 0.18};
    auto scheduled = test::scheduleRealSizePass(bladeSpec, 40);
    if (!scheduled || scheduled->layers.size() < 3) {
        std::fprintf(stderr, "schedule failed\n");
        std::abort();
    }
    const std::size_t middle = scheduled->layers.size() / 2;
    return optimal::boundsOf(scheduled->layers[middle], false, false);
}

const optimal::LayerBounds& layer() {
    static const optimal::LayerBounds bounds = realSizeLayer();
    return bounds;
}

// The LP in GLPK's form: free columns, rows A x <= b and E x = d (GLPK arrays are 1-based).
void loadIntoGlpk(const optimal::ConvexProgram& lp, glp_prob* problem) {
    const auto columns = static_cast<int>(lp.c.size());
    glp_set_obj_dir(problem, GLP_MIN);
    glp_add_cols(problem, columns);
    for (int j = 0; j < columns; ++j) {
        glp_set_col_bnds(problem, j + 1, GLP_FR, 0.0, 0.0);
        glp_set_obj_coef(problem, j + 1, lp.c[j]);
    }
    std::vector<int> rows{0}, cols{0};
    std::vector<double> values{0.0};
    const auto add = [&](const Sparse& matrix, int firstRow) {
        for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
            for (Sparse::InnerIterator it(matrix, col); it; ++it) {
                rows.push_back(firstRow + static_cast<int>(it.row()));
                cols.push_back(static_cast<int>(it.col()) + 1);
                values.push_back(it.value());
            }
        }
    };
    const auto inequalities = static_cast<int>(lp.A.rows());
    glp_add_rows(problem, inequalities + static_cast<int>(lp.E.rows()));
    for (int r = 0; r < inequalities; ++r) {
        glp_set_row_bnds(problem, r + 1, GLP_UP, 0.0, lp.b[r]);
    }
    for (int r = 0; r < static_cast<int>(lp.E.rows()); ++r) {
        glp_set_row_bnds(problem, inequalities + r + 1, GLP_FX, lp.d[r], lp.d[r]);
    }
    add(lp.A, 1);
    add(lp.E, inequalities + 1);
    glp_load_matrix(problem, static_cast<int>(values.size()) - 1, rows.data(), cols.data(),
                    values.data());
}

// Our interior point on `program`, once per iteration.
void runOwnInteriorPoint(benchmark::State& state, const optimal::ConvexProgram& program) {
    double objective = 0.0;
    for (auto _ : state) {
        auto solution = optimal::solveInteriorPoint(program);
        if (!solution) {
            state.SkipWithError(solution.error().message.c_str());
            return;
        }
        objective = solution->objective;
    }
    state.counters["objective"] = objective;
}

void BM_MinimumPeakLp_OwnInteriorPoint(benchmark::State& state) {
    runOwnInteriorPoint(state, optimal::minimumPeakProgram(layer()));
}
BENCHMARK(BM_MinimumPeakLp_OwnInteriorPoint)->Unit(benchmark::kMillisecond);

// Solves the layer's LP with GLPK once per iteration: `solve` runs one GLPK method on the loaded
// problem and returns its optimum, or nothing when GLPK found none.
template <class Solve>
void runGlpk(benchmark::State& state, const char* method, Solve&& solve) {
    const optimal::ConvexProgram lp = optimal::minimumPeakProgram(layer());
    double objective = 0.0;
    for (auto _ : state) {
        glp_prob* problem = glp_create_prob();
        loadIntoGlpk(lp, problem);
        const std::optional<double> optimum = solve(problem);
        glp_delete_prob(problem);
        if (!optimum) {
            state.SkipWithError((std::string("GLPK ") + method + " found no optimum").c_str());
            return;
        }
        objective = *optimum;
    }
    state.counters["objective"] = objective;
}

void BM_MinimumPeakLp_GlpkSimplex(benchmark::State& state) {
    runGlpk(state, "simplex", [](glp_prob* problem) -> std::optional<double> {
        glp_smcp parameters;
        glp_init_smcp(&parameters);
        parameters.msg_lev = GLP_MSG_OFF;
        parameters.presolve = GLP_ON;
        if (glp_simplex(problem, &parameters) != 0 || glp_get_status(problem) != GLP_OPT) {
            return std::nullopt;
        }
        return glp_get_obj_val(problem);
    });
}
BENCHMARK(BM_MinimumPeakLp_GlpkSimplex)->Unit(benchmark::kMillisecond);

void BM_MinimumPeakLp_GlpkInteriorPoint(benchmark::State& state) {
    runGlpk(state, "interior point", [](glp_prob* problem) -> std::optional<double> {
        glp_iptcp parameters;
        glp_init_iptcp(&parameters);
        parameters.msg_lev = GLP_MSG_OFF;
        if (glp_interior(problem, &parameters) != 0 || glp_ipt_status(problem) != GLP_OPT) {
            return std::nullopt;
        }
        return glp_ipt_obj_val(problem);
    });
}
BENCHMARK(BM_MinimumPeakLp_GlpkInteriorPoint)->Unit(benchmark::kMillisecond);

void BM_SmoothestQp_OwnInteriorPoint(benchmark::State& state) {
    runOwnInteriorPoint(state, optimal::smoothestProgram(layer()));
}
BENCHMARK(BM_SmoothestQp_OwnInteriorPoint)->Unit(benchmark::kMillisecond);

// ALGLIB's sparse interior point with the same rows: A x <= b one-sided, E x = d two-sided.
void BM_SmoothestQp_AlglibSparseInteriorPoint(benchmark::State& state) {
    const optimal::ConvexProgram qp = optimal::smoothestProgram(layer());
    const auto n = static_cast<alglib::ae_int_t>(qp.c.size());
    const auto k = static_cast<alglib::ae_int_t>(qp.A.rows() + qp.E.rows());
    double objective = 0.0, violation = 0.0;
    for (auto _ : state) {
        alglib::sparsematrix hessian, rows;
        alglib::sparsecreate(n, n, hessian);
        for (Eigen::Index col = 0; col < qp.P.outerSize(); ++col) {
            for (Sparse::InnerIterator it(qp.P, col); it; ++it) {
                if (it.row() <= it.col()) {
                    alglib::sparseset(hessian, it.row(), it.col(), it.value());
                }
            }
        }
        alglib::sparsecreate(k, n, rows);
        alglib::real_1d_array lower, upper, linear, x;
        lower.setlength(k);
        upper.setlength(k);
        linear.setlength(n);
        for (alglib::ae_int_t j = 0; j < n; ++j) {
            linear[j] = qp.c[j];
        }
        const auto add = [&](const Sparse& matrix, alglib::ae_int_t firstRow) {
            for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
                for (Sparse::InnerIterator it(matrix, col); it; ++it) {
                    alglib::sparseset(rows, firstRow + it.row(), it.col(), it.value());
                }
            }
        };
        add(qp.A, 0);
        add(qp.E, qp.A.rows());
        for (Eigen::Index r = 0; r < qp.A.rows(); ++r) {
            lower[r] = alglib::fp_neginf;
            upper[r] = qp.b[r];
        }
        for (Eigen::Index r = 0; r < qp.E.rows(); ++r) {
            lower[qp.A.rows() + r] = upper[qp.A.rows() + r] = qp.d[r];
        }
        alglib::sparseconverttocrs(rows);
        alglib::minqpstate solver;
        alglib::minqpreport report;
        alglib::minqpcreate(n, solver);
        alglib::minqpsetquadratictermsparse(solver, hessian, true);
        alglib::minqpsetlinearterm(solver, linear);
        alglib::minqpsetlc2(solver, rows, lower, upper, k);
        alglib::minqpsetscaleautodiag(solver);
        alglib::minqpsetalgosparseipm(solver, 1e-9);
        alglib::minqpoptimize(solver);
        alglib::minqpresults(solver, x, report);
        if (report.terminationtype <= 0) {
            state.SkipWithError("ALGLIB sparse interior point found no optimum");
            return;
        }
        Eigen::VectorXd solution(n);
        for (alglib::ae_int_t j = 0; j < n; ++j) {
            solution[j] = x[j];
        }
        objective = 0.5 * solution.dot(qp.P * solution) + qp.c.dot(solution);
        violation = std::max((qp.A * solution - qp.b).maxCoeff(),
                             (qp.E * solution - qp.d).cwiseAbs().maxCoeff());
    }
    state.counters["objective"] = objective;
    state.counters["violation"] = violation; // largest constraint violation of its answer, rad
}
BENCHMARK(BM_SmoothestQp_AlglibSparseInteriorPoint)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
