#include "core/optimal/layer_optimum.h"

#include "core/optimal/interior_point_lp.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace bladeaxis::optimal {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
using Triplet = Eigen::Triplet<double>;

// Rows of D2 (interior samples) as triplets, column offset 0.
void addSecondDifferenceRow(std::span<const double> s, std::size_t i, double scale,
                            Eigen::Index row, std::vector<Triplet>& triplets) {
    const double before = s[i] - s[i - 1], after = s[i + 1] - s[i];
    const double c = 2.0 / (before + after);
    const auto col = static_cast<Eigen::Index>(i);
    triplets.emplace_back(row, col - 1, scale * c / before);
    triplets.emplace_back(row, col, -scale * c * (1.0 / before + 1.0 / after));
    triplets.emplace_back(row, col + 1, scale * c / after);
}

struct Rows {
    std::vector<Triplet> triplets;
    std::vector<double> lower, upper;
    Eigen::Index count = 0;

    void add(std::initializer_list<std::pair<Eigen::Index, double>> entries, double lo, double hi) {
        for (const auto& [col, value] : entries) {
            triplets.emplace_back(count, col, value);
        }
        lower.push_back(lo);
        upper.push_back(hi);
        ++count;
    }
};

// Bounds, monotone differences and the junction conditions, on the first n variables.
void addScheduleRows(const LayerBounds& b, Rows& rows) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    for (Eigen::Index i = 0; i < n; ++i) {
        rows.add({{i, 1.0}}, b.lower[static_cast<std::size_t>(i)],
                 b.upper[static_cast<std::size_t>(i)]);
    }
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
        rows.add({{i, -1.0}, {i + 1, 1.0}}, 0.0, kInfinity);
    }
    if (!b.freeStart) {
        rows.add({{0, 1.0}}, b.start, b.start);
        rows.add({{0, -1.0}, {1, 1.0}}, 0.0, 0.0);
    }
    if (!b.freeEnd) {
        rows.add({{n - 1, 1.0}}, b.end, b.end);
        rows.add({{n - 2, -1.0}, {n - 1, 1.0}}, 0.0, 0.0);
    }
}

QpProblem smoothestQp(const LayerBounds& b) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    std::vector<Triplet> d2;
    for (std::size_t i = 1; i + 1 < b.s.size(); ++i) {
        // sqrt(w_i) folded into the row, so D' D is the weighted Hessian.
        const double weight = 0.5 * (b.s[i + 1] - b.s[i - 1]);
        addSecondDifferenceRow(b.s, i, std::sqrt(weight), static_cast<Eigen::Index>(i - 1), d2);
    }
    SparseMatrix D(n - 2, n);
    D.setFromTriplets(d2.begin(), d2.end());
    Rows rows;
    addScheduleRows(b, rows);
    QpProblem qp;
    qp.P = 2.0 * SparseMatrix(D.transpose() * D); // 1/2 x'Px = sum w D2^2
    qp.q = Vector::Zero(n);
    qp.M.resize(rows.count, n);
    qp.M.setFromTriplets(rows.triplets.begin(), rows.triplets.end());
    qp.lower = Eigen::Map<const Vector>(rows.lower.data(), rows.count);
    qp.upper = Eigen::Map<const Vector>(rows.upper.data(), rows.count);
    return qp;
}

// Epigraph form: variables (theta, t), minimise t with -t <= (L^2 / 4) D2_i theta <= t. The
// scale makes t the angle a bang-bang profile of that peak covers over the layer (the §9.4
// oracle), i.e. of the order of the angles, which keeps the interior point well conditioned.
SparseLp minimumPeakLp(const LayerBounds& b) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    const double length = b.s.back() - b.s.front();
    const double scale = 0.25 * length * length;
    std::vector<Triplet> inequality, equality;
    std::vector<double> rhs, equalityRhs;
    auto addRow = [&](std::vector<Triplet>& rows, std::vector<double>& values,
                      std::initializer_list<std::pair<Eigen::Index, double>> entries,
                      double value) {
        const auto row = static_cast<Eigen::Index>(values.size());
        for (const auto& [col, coefficient] : entries) {
            rows.emplace_back(row, col, coefficient);
        }
        values.push_back(value);
    };
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        addRow(inequality, rhs, {{i, 1.0}}, b.upper[k]);
        addRow(inequality, rhs, {{i, -1.0}}, -b.lower[k]);
        if (i + 1 < n) {
            addRow(inequality, rhs, {{i, 1.0}, {i + 1, -1.0}}, 0.0); // monotone
        }
    }
    for (std::size_t i = 1; i + 1 < b.s.size(); ++i) {
        for (double sign : {1.0, -1.0}) {
            const auto row = static_cast<Eigen::Index>(rhs.size());
            addSecondDifferenceRow(b.s, i, sign * scale, row, inequality);
            inequality.emplace_back(row, n, -1.0);
            rhs.push_back(0.0);
        }
    }
    if (!b.freeStart) {
        addRow(equality, equalityRhs, {{0, 1.0}}, b.start);
        addRow(equality, equalityRhs, {{0, -1.0}, {1, 1.0}}, 0.0);
    }
    if (!b.freeEnd) {
        addRow(equality, equalityRhs, {{n - 1, 1.0}}, b.end);
        addRow(equality, equalityRhs, {{n - 2, -1.0}, {n - 1, 1.0}}, 0.0);
    }
    SparseLp lp;
    lp.c = Vector::Zero(n + 1);
    lp.c[n] = 1.0;
    lp.A.resize(static_cast<Eigen::Index>(rhs.size()), n + 1);
    lp.A.setFromTriplets(inequality.begin(), inequality.end());
    lp.b = Eigen::Map<const Vector>(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
    lp.E.resize(static_cast<Eigen::Index>(equalityRhs.size()), n + 1);
    lp.E.setFromTriplets(equality.begin(), equality.end());
    lp.d =
        Eigen::Map<const Vector>(equalityRhs.data(), static_cast<Eigen::Index>(equalityRhs.size()));
    return lp;
}

Status validate(const LayerBounds& b) {
    const std::size_t n = b.s.size();
    if (n < 4 || b.lower.size() != n || b.upper.size() != n) {
        return makeError(ErrorCode::InvalidArgument,
                         "a layer of the optimum needs at least 4 samples with bounds");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(b.s[i]) || std::isnan(b.lower[i]) || std::isnan(b.upper[i]) ||
            b.lower[i] > b.upper[i] || (i > 0 && !(b.s[i] > b.s[i - 1]))) {
            return makeError(ErrorCode::InvalidArgument,
                             "layer bounds at sample " + std::to_string(i) +
                                 ": S must increase and lower <= upper");
        }
    }
    return {};
}

} // namespace

LayerBounds boundsOf(const scheduling::LayerResult& layer, bool firstLayer, bool lastLayer) {
    LayerBounds b;
    b.s = layer.s;
    b.lower = layer.lo;
    b.upper = layer.hi;
    b.start = layer.theta.empty() ? 0.0 : layer.theta.front();
    b.end = layer.theta.empty() ? 0.0 : layer.theta.back();
    b.freeStart = firstLayer;
    b.freeEnd = lastLayer;
    return b;
}

std::vector<double> secondDifferences(std::span<const double> s, std::span<const double> theta) {
    const std::size_t n = std::min(s.size(), theta.size());
    std::vector<double> d2(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double before = s[i] - s[i - 1], after = s[i + 1] - s[i];
        if (before > 0.0 && after > 0.0) {
            d2[i] = 2.0 * ((theta[i + 1] - theta[i]) / after - (theta[i] - theta[i - 1]) / before) /
                    (before + after);
        }
    }
    return d2;
}

double peakSecondDifference(std::span<const double> s, std::span<const double> theta) {
    double peak = 0.0;
    for (double value : secondDifferences(s, theta)) {
        peak = std::max(peak, std::abs(value));
    }
    return peak;
}

double secondDifferenceEnergy(std::span<const double> s, std::span<const double> theta) {
    const auto d2 = secondDifferences(s, theta);
    double energy = 0.0;
    for (std::size_t i = 1; i + 1 < d2.size(); ++i) {
        energy += 0.5 * (s[i + 1] - s[i - 1]) * d2[i] * d2[i];
    }
    return energy;
}

Result<LayerOptimum> smoothestLayer(const LayerBounds& bounds, const AdmmSettings& settings) {
    if (auto status = validate(bounds); !status) {
        return std::unexpected(status.error());
    }
    const auto started = std::chrono::steady_clock::now();
    auto solution = solveQp(smoothestQp(bounds), settings);
    if (!solution) {
        return std::unexpected(solution.error());
    }
    if (!solution->converged) {
        return makeError(ErrorCode::Infeasible, "the optimum did not converge in " +
                                                    std::to_string(solution->iterations) +
                                                    " iterations (primal residual " +
                                                    std::to_string(solution->primalResidual) + ")");
    }
    LayerOptimum optimum;
    const auto n = static_cast<Eigen::Index>(bounds.s.size());
    optimum.theta.assign(solution->x.data(), solution->x.data() + n);
    optimum.peakSecondDifference = peakSecondDifference(bounds.s, optimum.theta);
    optimum.secondDifferenceEnergy = secondDifferenceEnergy(bounds.s, optimum.theta);
    optimum.solver = std::move(*solution);
    optimum.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return optimum;
}

Result<LayerOptimum> minimumPeakLayer(const LayerBounds& bounds) {
    if (auto status = validate(bounds); !status) {
        return std::unexpected(status.error());
    }
    const auto started = std::chrono::steady_clock::now();
    auto solution = solveLp(minimumPeakLp(bounds));
    if (!solution) {
        return std::unexpected(solution.error());
    }
    LayerOptimum optimum;
    const auto n = static_cast<Eigen::Index>(bounds.s.size());
    optimum.theta.assign(solution->x.data(), solution->x.data() + n);
    optimum.peakSecondDifference = peakSecondDifference(bounds.s, optimum.theta);
    optimum.secondDifferenceEnergy = secondDifferenceEnergy(bounds.s, optimum.theta);
    optimum.solver.iterations = solution->iterations;
    optimum.solver.converged = solution->converged;
    optimum.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return optimum;
}

Result<PathOptimum> optimalPath(const scheduling::ScheduleResult& reference, Objective objective) {
    const auto started = std::chrono::steady_clock::now();
    const std::size_t n = reference.thetaAbsolute.size();
    PathOptimum path;
    path.thetaAbsolute.assign(n, std::numeric_limits<double>::quiet_NaN());
    const auto& layers = reference.layers;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        auto optimum =
            objective == Objective::SmoothestQp ? smoothestLayer(bounds) : minimumPeakLayer(bounds);
        if (!optimum) {
            Error error = optimum.error();
            error.message = "layer " + std::to_string(k + 1) + ": " + error.message;
            return std::unexpected(error);
        }
        for (std::size_t j = 0; j < layers[k].inputIndex.size(); ++j) {
            path.thetaAbsolute[layers[k].inputIndex[j]] =
                layers[k].junctionAngle + optimum->theta[j];
        }
        ++path.layers;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(path.thetaAbsolute[i])) { // a merged duplicate: its sample precedes it
            path.thetaAbsolute[i] = i > 0 ? path.thetaAbsolute[i - 1] : reference.thetaAbsolute[i];
        }
    }
    path.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return path;
}

} // namespace bladeaxis::optimal
