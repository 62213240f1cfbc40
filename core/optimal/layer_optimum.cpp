#include "core/optimal/layer_optimum.h"

#include "core/analysis/motion_knots.h"
#include "core/optimal/interior_point.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace bladeaxis::optimal {

namespace {

using Triplet = Eigen::Triplet<double>;
using SparseMatrix = Eigen::SparseMatrix<double>;
using Vector = Eigen::VectorXd;

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

// Bounds and monotone differences as rows A x <= b, and the junction conditions as rows
// E x = d, on the first n variables.
struct LayerRows {
    std::vector<Triplet> inequality, equality;
    std::vector<double> rhs, equalityRhs;

    static void add(std::vector<Triplet>& rows, std::vector<double>& values,
                    std::initializer_list<std::pair<Eigen::Index, double>> entries, double value) {
        const auto row = static_cast<Eigen::Index>(values.size());
        for (const auto& [col, coefficient] : entries) {
            rows.emplace_back(row, col, coefficient);
        }
        values.push_back(value);
    }
    void lessEqual(std::initializer_list<std::pair<Eigen::Index, double>> entries, double value) {
        add(inequality, rhs, entries, value);
    }
    void equal(std::initializer_list<std::pair<Eigen::Index, double>> entries, double value) {
        add(equality, equalityRhs, entries, value);
    }

    void into(ConvexProgram& problem, Eigen::Index columns) const {
        problem.A.resize(static_cast<Eigen::Index>(rhs.size()), columns);
        problem.A.setFromTriplets(inequality.begin(), inequality.end());
        problem.b = Eigen::Map<const Vector>(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
        problem.E.resize(static_cast<Eigen::Index>(equalityRhs.size()), columns);
        problem.E.setFromTriplets(equality.begin(), equality.end());
        problem.d = Eigen::Map<const Vector>(equalityRhs.data(),
                                             static_cast<Eigen::Index>(equalityRhs.size()));
    }
};

void addScheduleRows(const LayerBounds& b, LayerRows& rows) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        rows.lessEqual({{i, 1.0}}, b.upper[k]);
        rows.lessEqual({{i, -1.0}}, -b.lower[k]);
        if (i + 1 < n) {
            rows.lessEqual({{i, 1.0}, {i + 1, -1.0}}, 0.0); // monotone
        }
    }
    if (!b.freeStart) {
        rows.equal({{0, 1.0}}, b.start);
        if (!b.mirroredStart && !b.freeStartSlope) {
            rows.equal({{0, -1.0}, {1, 1.0}}, 0.0);
        }
    }
    if (!b.freeEnd) {
        rows.equal({{n - 1, 1.0}}, b.end);
        if (!b.mirroredEnd && !b.freeEndSlope) {
            rows.equal({{n - 2, -1.0}, {n - 1, 1.0}}, 0.0);
        }
    }
}

} // namespace

// 1/2 theta' P theta = sum w_i D2_i^2 (times a constant).
ConvexProgram smoothestProgram(const LayerBounds& b) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    std::vector<Triplet> d2;
    const std::vector<SecondDifferenceRow> objective = objectiveRows(b);
    for (std::size_t r = 0; r < objective.size(); ++r) {
        // sqrt(w_i) folded into the row, so D' D is the weighted Hessian.
        addRow(objective[r], std::sqrt(objective[r].weight), static_cast<Eigen::Index>(r), d2);
    }
    SparseMatrix D(static_cast<Eigen::Index>(objective.size()), n);
    D.setFromTriplets(d2.begin(), d2.end());
    // Scaled by L^3 / 12: the cubic of spec §9.4 then has the objective theta_e^2, an angle
    // squared, the scale the interior point's relative gap is measured against.
    const double length = b.s.back() - b.s.front();
    const double scale = std::pow(length, 3) / 12.0;
    ConvexProgram qp;
    qp.P = 2.0 * scale * SparseMatrix(D.transpose() * D);
    qp.c = Vector::Zero(n);
    LayerRows rows;
    addScheduleRows(b, rows);
    rows.into(qp, n);
    return qp;
}

// Epigraph form: variables (theta, t), minimise t with -t <= (L^2 / 4) D2_i theta <= t. The
// scale makes t the angle a bang-bang profile of that peak covers over the layer (the §9.4
// oracle), i.e. of the order of the angles, which keeps the interior point well conditioned.
ConvexProgram minimumPeakProgram(const LayerBounds& b) {
    const auto n = static_cast<Eigen::Index>(b.s.size());
    const double length = b.s.back() - b.s.front();
    const double scale = 0.25 * length * length;
    LayerRows rows;
    addScheduleRows(b, rows);
    for (const SecondDifferenceRow& d2 : objectiveRows(b)) {
        for (double sign : {1.0, -1.0}) {
            const auto row = static_cast<Eigen::Index>(rows.rhs.size());
            addRow(d2, sign * scale, row, rows.inequality);
            rows.inequality.emplace_back(row, n, -1.0);
            rows.rhs.push_back(0.0);
        }
    }
    ConvexProgram lp;
    lp.c = Vector::Zero(n + 1);
    lp.c[n] = 1.0;
    rows.into(lp, n + 1);
    return lp;
}

namespace {

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

namespace {

// The monotone hull of the raw channel: a non-decreasing theta inside [thetaMin, thetaMax] lies
// below every later thetaMax and above every earlier thetaMin, and any theta between these
// running bounds can be made so.
void rawMonotoneHull(const scheduling::LayerResult& layer, LayerBounds& b) {
    const std::size_t n = layer.thetaMin.size();
    b.lower.resize(n);
    b.upper.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        b.lower[i] = i == 0 ? layer.thetaMin[0] : std::max(b.lower[i - 1], layer.thetaMin[i]);
    }
    for (std::size_t i = n; i-- > 0;) {
        b.upper[i] = i + 1 == n ? layer.thetaMax[i] : std::min(b.upper[i + 1], layer.thetaMax[i]);
    }
}

} // namespace

LayerBounds boundsOf(const scheduling::LayerResult& layer, bool firstLayer, bool lastLayer,
                     OptimumConstraints constraints) {
    LayerBounds b;
    b.s = layer.s;
    const bool likeTheEngine = constraints == OptimumConstraints::LikeTheEngine;
    if (likeTheEngine && layer.thetaMin.size() == layer.s.size() &&
        layer.thetaMax.size() == layer.s.size()) {
        rawMonotoneHull(layer, b);
    } else {
        b.lower = layer.lo;
        b.upper = layer.hi;
    }
    b.start = layer.theta.empty() ? 0.0 : layer.theta.front();
    b.end = layer.theta.empty() ? 0.0 : layer.theta.back();
    b.freeStart = firstLayer && !likeTheEngine;
    b.freeEnd = lastLayer && !likeTheEngine;
    b.freeStartSlope = firstLayer && likeTheEngine;
    b.freeEndSlope = lastLayer && likeTheEngine;
    const std::size_t n = b.s.size();
    auto fits = [&](double value, std::size_t i) {
        return i < n && value >= b.lower[i] && value <= b.upper[i];
    };
    b.mirroredStart = !b.freeStart && !b.freeStartSlope && n > 1 && !fits(b.start, 1);
    b.mirroredEnd = !b.freeEnd && !b.freeEndSlope && n > 1 && !fits(b.end, n - 2);
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

namespace {

Result<LayerOptimum> solveLayerProgram(const LayerBounds& bounds, const ConvexProgram& problem) {
    const auto started = std::chrono::steady_clock::now();
    auto solution = solveInteriorPoint(problem);
    if (!solution) {
        return std::unexpected(solution.error());
    }
    LayerOptimum optimum;
    const auto n = static_cast<Eigen::Index>(bounds.s.size());
    optimum.theta.assign(solution->x.data(), solution->x.data() + n);
    optimum.peakSecondDifference = peakSecondDifference(bounds, optimum.theta);
    optimum.secondDifferenceEnergy = secondDifferenceEnergy(bounds, optimum.theta);
    optimum.iterations = solution->iterations;
    optimum.relativeResidual = solution->relativeResidual;
    optimum.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return optimum;
}

} // namespace

Result<LayerOptimum> smoothestLayer(const LayerBounds& bounds) {
    if (auto status = validate(bounds); !status) {
        return std::unexpected(status.error());
    }
    return solveLayerProgram(bounds, smoothestProgram(bounds));
}

Result<LayerOptimum> minimumPeakLayer(const LayerBounds& bounds) {
    if (auto status = validate(bounds); !status) {
        return std::unexpected(status.error());
    }
    return solveLayerProgram(bounds, minimumPeakProgram(bounds));
}

namespace {

// A chord shorter than a tenth of the layer's median chord (analysis::MotionKnotTolerances,
// the same rule the figures use) is a split of a move (posts write micrometre chords), not a
// place where the schedule can bend: the optimum is solved without such samples. Kept in the
// problem, a 2 um chord makes its second differences dominate and the optimum answers another
// question than on the same path without the split.
// The samples of the problem, without those a short chord away from the previous kept one (the
// first and the last always kept).
std::vector<std::size_t> samplesWithoutShortChords(std::span<const double> s) {
    const double shortChord =
        analysis::MotionKnotTolerances{}.shortChordFraction * analysis::medianChord(s);
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

} // namespace

std::vector<std::size_t> problemSamples(std::span<const double> s) {
    std::vector<std::size_t> kept = samplesWithoutShortChords(s);
    if (kept.size() < s.size() && kept.size() >= 4) {
        return kept;
    }
    kept.resize(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        kept[i] = i;
    }
    return kept;
}

Result<std::vector<double>> optimalLayer(const LayerBounds& bounds, Objective objective) {
    const std::vector<std::size_t> kept = problemSamples(bounds.s);
    const bool thinned = kept.size() < bounds.s.size();
    const LayerBounds problem = thinned ? keepSamples(bounds, kept) : bounds;
    auto optimum =
        objective == Objective::SmoothestQp ? smoothestLayer(problem) : minimumPeakLayer(problem);
    if (!optimum) {
        return std::unexpected(optimum.error());
    }
    return thinned ? atEverySample(bounds, kept, optimum->theta) : std::move(optimum->theta);
}

Result<PathOptimum> optimalPath(const scheduling::ScheduleResult& reference, Objective objective) {
    const auto started = std::chrono::steady_clock::now();
    const std::size_t n = reference.newAxes.size();
    PathOptimum path;
    path.thetaAbsolute.assign(n, std::numeric_limits<double>::quiet_NaN());
    const auto& layers = reference.layers;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        auto theta = optimalLayer(bounds, objective);
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
            path.thetaAbsolute[i] =
                i > 0 ? path.thetaAbsolute[i - 1]
                      : absoluteAngles(reference, scheduling::Orientation::Rescheduled)[i];
        }
    }
    path.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return path;
}

} // namespace bladeaxis::optimal
