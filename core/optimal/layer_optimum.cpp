#include "core/optimal/layer_optimum.h"

#include "core/optimal/interior_point_lp.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace bladeaxis::optimal {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
using Triplet = Eigen::Triplet<double>;

// One second difference of the objective: D2 = sum coefficient * theta[column], weighted by
// the length of S it stands for (w_i of spec §9.1).
struct SecondDifferenceRow {
    std::array<std::pair<Eigen::Index, double>, 3> terms{};
    std::size_t count = 0;
    double weight = 0.0;

    double at(std::span<const double> theta) const {
        double value = 0.0;
        for (std::size_t k = 0; k < count; ++k) {
            value += terms[k].second * theta[static_cast<std::size_t>(terms[k].first)];
        }
        return value;
    }
};

// D2 at an interior sample i (spec §9.1).
SecondDifferenceRow interiorRow(std::span<const double> s, std::size_t i) {
    const double before = s[i] - s[i - 1], after = s[i + 1] - s[i];
    const double c = 2.0 / (before + after);
    const auto col = static_cast<Eigen::Index>(i);
    return {
        {{{col - 1, c / before}, {col, -c * (1.0 / before + 1.0 / after)}, {col + 1, c / after}}},
        3,
        0.5 * (before + after)};
}

// D2 at the end sample `end` with its neighbour `inner` mirrored beyond it (theta' = 0 there):
// 2 (theta_inner - theta_end) / h^2, standing for the half step inside the layer.
SecondDifferenceRow mirroredRow(std::span<const double> s, std::size_t end, std::size_t inner) {
    const double h = std::abs(s[inner] - s[end]);
    const double c = 2.0 / (h * h);
    return {{{{static_cast<Eigen::Index>(end), -c}, {static_cast<Eigen::Index>(inner), c}, {}}},
            2,
            0.5 * h};
}

// Every second difference the objectives measure, for bounds with at least 3 samples.
std::vector<SecondDifferenceRow> objectiveRows(const LayerBounds& b) {
    const std::size_t n = b.s.size();
    std::vector<SecondDifferenceRow> rows;
    rows.reserve(n);
    if (b.mirroredStart && !b.freeStart) {
        rows.push_back(mirroredRow(b.s, 0, 1));
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        rows.push_back(interiorRow(b.s, i));
    }
    if (b.mirroredEnd && !b.freeEnd) {
        rows.push_back(mirroredRow(b.s, n - 1, n - 2));
    }
    return rows;
}

void addRow(const SecondDifferenceRow& row, double scale, Eigen::Index rowIndex,
            std::vector<Triplet>& triplets) {
    for (std::size_t k = 0; k < row.count; ++k) {
        triplets.emplace_back(rowIndex, row.terms[k].first, scale * row.terms[k].second);
    }
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
        if (!b.mirroredStart) {
            rows.add({{0, -1.0}, {1, 1.0}}, 0.0, 0.0);
        }
    }
    if (!b.freeEnd) {
        rows.add({{n - 1, 1.0}}, b.end, b.end);
        if (!b.mirroredEnd) {
            rows.add({{n - 2, -1.0}, {n - 1, 1.0}}, 0.0, 0.0);
        }
    }
}

QpProblem smoothestQp(const LayerBounds& b) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    std::vector<Triplet> d2;
    const std::vector<SecondDifferenceRow> objective = objectiveRows(b);
    for (std::size_t r = 0; r < objective.size(); ++r) {
        // sqrt(w_i) folded into the row, so D' D is the weighted Hessian.
        addRow(objective[r], std::sqrt(objective[r].weight), static_cast<Eigen::Index>(r), d2);
    }
    SparseMatrix D(static_cast<Eigen::Index>(objective.size()), n);
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
    auto add = [&](std::vector<Triplet>& rows, std::vector<double>& values,
                   std::initializer_list<std::pair<Eigen::Index, double>> entries, double value) {
        const auto row = static_cast<Eigen::Index>(values.size());
        for (const auto& [col, coefficient] : entries) {
            rows.emplace_back(row, col, coefficient);
        }
        values.push_back(value);
    };
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        add(inequality, rhs, {{i, 1.0}}, b.upper[k]);
        add(inequality, rhs, {{i, -1.0}}, -b.lower[k]);
        if (i + 1 < n) {
            add(inequality, rhs, {{i, 1.0}, {i + 1, -1.0}}, 0.0); // monotone
        }
    }
    for (const SecondDifferenceRow& d2 : objectiveRows(b)) {
        for (double sign : {1.0, -1.0}) {
            const auto row = static_cast<Eigen::Index>(rhs.size());
            addRow(d2, sign * scale, row, inequality);
            inequality.emplace_back(row, n, -1.0);
            rhs.push_back(0.0);
        }
    }
    if (!b.freeStart) {
        add(equality, equalityRhs, {{0, 1.0}}, b.start);
        if (!b.mirroredStart) {
            add(equality, equalityRhs, {{0, -1.0}, {1, 1.0}}, 0.0);
        }
    }
    if (!b.freeEnd) {
        add(equality, equalityRhs, {{n - 1, 1.0}}, b.end);
        if (!b.mirroredEnd) {
            add(equality, equalityRhs, {{n - 2, -1.0}, {n - 1, 1.0}}, 0.0);
        }
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
    const std::size_t n = b.s.size();
    auto fits = [&](double value, std::size_t i) {
        return i < n && value >= b.lower[i] && value <= b.upper[i];
    };
    b.mirroredStart = !firstLayer && n > 1 && !fits(b.start, 1);
    b.mirroredEnd = !lastLayer && n > 1 && !fits(b.end, n - 2);
    return b;
}

double peakSecondDifference(const LayerBounds& bounds, std::span<const double> theta) {
    double peak = 0.0;
    if (bounds.s.size() >= 3 && theta.size() == bounds.s.size()) {
        for (const SecondDifferenceRow& row : objectiveRows(bounds)) {
            peak = std::max(peak, std::abs(row.at(theta)));
        }
    }
    return peak;
}

double secondDifferenceEnergy(const LayerBounds& bounds, std::span<const double> theta) {
    double energy = 0.0;
    if (bounds.s.size() >= 3 && theta.size() == bounds.s.size()) {
        for (const SecondDifferenceRow& row : objectiveRows(bounds)) {
            const double d2 = row.at(theta);
            energy += row.weight * d2 * d2;
        }
    }
    return energy;
}

// Without mirrored ends, the rows are the interior D2_i: the same objectives of any schedule.
double peakSecondDifference(std::span<const double> s, std::span<const double> theta) {
    LayerBounds samples;
    samples.s.assign(s.begin(), s.end());
    return peakSecondDifference(samples, theta);
}

double secondDifferenceEnergy(std::span<const double> s, std::span<const double> theta) {
    LayerBounds samples;
    samples.s.assign(s.begin(), s.end());
    return secondDifferenceEnergy(samples, theta);
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
    optimum.peakSecondDifference = peakSecondDifference(bounds, optimum.theta);
    optimum.secondDifferenceEnergy = secondDifferenceEnergy(bounds, optimum.theta);
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
    optimum.peakSecondDifference = peakSecondDifference(bounds, optimum.theta);
    optimum.secondDifferenceEnergy = secondDifferenceEnergy(bounds, optimum.theta);
    optimum.solver.iterations = solution->iterations;
    optimum.solver.converged = solution->converged;
    optimum.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return optimum;
}

namespace {

// A chord shorter than this fraction of the layer's median chord is a split of a move (posts
// write micrometre chords), not a place where the schedule can bend: the figures merge such
// samples (analysis/motion_knots.h), and the optimum is solved without them too. Kept in the
// problem, a 2 um chord makes its second differences dominate and the optimum answers another
// question than on the same path without the split.
constexpr double kShortChordFraction = 0.1;

double medianStep(std::span<const double> s) {
    std::vector<double> steps;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        steps.push_back(s[i + 1] - s[i]);
    }
    if (steps.empty()) {
        return 0.0;
    }
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    return *middle;
}

// The samples of the problem, without those a short chord away from the previous kept one (the
// first and the last always kept).
std::vector<std::size_t> samplesWithoutShortChords(std::span<const double> s) {
    const double shortChord = kShortChordFraction * medianStep(s);
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool last = i + 1 == s.size();
        if (kept.empty() || s[i] - s[kept.back()] >= shortChord) {
            kept.push_back(i);
        } else if (last) {
            if (kept.size() > 1) {
                kept.back() = i; // the end sample carries the end condition
            } else {
                kept.push_back(i);
            }
        }
    }
    return kept;
}

LayerBounds keepSamples(const LayerBounds& bounds, std::span<const std::size_t> kept) {
    LayerBounds thinned = bounds;
    thinned.s.clear();
    thinned.lower.clear();
    thinned.upper.clear();
    for (const std::size_t i : kept) {
        thinned.s.push_back(bounds.s[i]);
        thinned.lower.push_back(bounds.lower[i]);
        thinned.upper.push_back(bounds.upper[i]);
    }
    return thinned;
}

// theta at every sample: the kept samples' values, linear in s between them, within each
// merged sample's own bounds.
std::vector<double> atEverySample(const LayerBounds& bounds, std::span<const std::size_t> kept,
                                  std::span<const double> keptTheta) {
    std::vector<double> theta(bounds.s.size());
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
        const std::size_t a = kept[k], b = kept[k + 1];
        for (std::size_t i = a; i < b; ++i) {
            const double t = (bounds.s[i] - bounds.s[a]) / (bounds.s[b] - bounds.s[a]);
            const double value = keptTheta[k] + t * (keptTheta[k + 1] - keptTheta[k]);
            theta[i] = i == a ? value : std::clamp(value, bounds.lower[i], bounds.upper[i]);
        }
    }
    theta[kept.back()] = keptTheta.back();
    return theta;
}

Result<std::vector<double>> solveLayer(const LayerBounds& bounds, Objective objective) {
    const std::vector<std::size_t> kept = samplesWithoutShortChords(bounds.s);
    const bool thinned = kept.size() < bounds.s.size() && kept.size() >= 4;
    const LayerBounds problem = thinned ? keepSamples(bounds, kept) : bounds;
    auto optimum =
        objective == Objective::SmoothestQp ? smoothestLayer(problem) : minimumPeakLayer(problem);
    if (!optimum) {
        return std::unexpected(optimum.error());
    }
    return thinned ? atEverySample(bounds, kept, optimum->theta) : std::move(optimum->theta);
}

} // namespace

Result<PathOptimum> optimalPath(const scheduling::ScheduleResult& reference, Objective objective) {
    const auto started = std::chrono::steady_clock::now();
    const std::size_t n = reference.thetaAbsolute.size();
    PathOptimum path;
    path.thetaAbsolute.assign(n, std::numeric_limits<double>::quiet_NaN());
    const auto& layers = reference.layers;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        auto theta = solveLayer(bounds, objective);
        if (!theta) {
            Error error = theta.error();
            error.message = "layer " + std::to_string(k + 1) + ": " + error.message;
            return std::unexpected(error);
        }
        for (std::size_t j = 0; j < layers[k].inputIndex.size(); ++j) {
            path.thetaAbsolute[layers[k].inputIndex[j]] = layers[k].junctionAngle + (*theta)[j];
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
