#include "core/analysis/axis_profile.h"

#include "core/analysis/derivatives.h"
#include "core/analysis/motion_knots.h"
#include "core/base/free_storage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace bladeaxis::analysis {

namespace {

std::string recordName(std::size_t index, int line) {
    std::string name = "record " + std::to_string(index);
    if (line > 0) {
        name += " (line " + std::to_string(line) + ")";
    }
    return name;
}

bool lentSeriesFit(const PathSamples& path) {
    const auto fits = [&](std::size_t lent) { return lent == 0 || lent == path.size(); };
    return fits(path.toolAxes.size()) && fits(path.feeds.size());
}

bool axesFinite(const kinematics::MachineAxes& m) {
    return std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z) && std::isfinite(m.a) &&
           std::isfinite(m.b);
}

// Also stores the positive programmed feeds, a run of one feed once, for chooseFeed: gathered in
// the same pass, as a pass over the records (over 100 bytes each) costs about as much as the
// checks.
Status validateInput(std::span<const kinematics::MachineAxes> axes, const PathSamples& path,
                     const AxisProfileOptions& options, std::vector<double>& feedRuns) {
    if (axes.size() != path.size()) {
        return makeError(ErrorCode::InvalidArgument, "axis motion: " + std::to_string(axes.size()) +
                                                         " axis sets for " +
                                                         std::to_string(path.size()) + " records");
    }
    if (!lentSeriesFit(path)) {
        return makeError(ErrorCode::InvalidArgument,
                         "axis motion: the new tool axes or feeds are not one per record");
    }
    // New axes over the records' own tips would move every ball centre: not a re-scheduled pass.
    if (!path.toolAxes.empty() && !(path.keptCentreRadius > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "axis motion: new tool axes are lent without the radius of the ball "
                         "centres they keep");
    }
    if (path.size() == 0) {
        return makeError(ErrorCode::InvalidArgument, "axis motion: no records to analyse");
    }
    if (path.size() - 1 > std::numeric_limits<RecordIndex>::max()) {
        return makeError(ErrorCode::InvalidArgument,
                         "axis motion: " + std::to_string(path.size()) +
                             " records, more than one analysis indexes");
    }
    if (!std::isfinite(options.feedOverride) || options.feedOverride < 0.0) {
        return makeError(ErrorCode::InvalidArgument, "feed override must be >= 0 mm/s, got " +
                                                         std::to_string(options.feedOverride));
    }
    const bool centre = options.feedReference == FeedReference::Centre;
    if (centre && !(options.toolRadius > 0.0 && std::isfinite(options.toolRadius))) {
        return makeError(ErrorCode::InvalidArgument,
                         "feed reference 'centre' needs a tool radius > 0 mm, got " +
                             std::to_string(options.toolRadius));
    }
    for (std::size_t i = 0; i < path.size(); ++i) {
        const bool poseOk = path.tip(i).allFinite() && (!centre || path.toolAxis(i).allFinite());
        if (!poseOk || !axesFinite(axes[i])) {
            return makeError(ErrorCode::Geometry, "non-finite tool pose or machine axis at " +
                                                      recordName(i, path.line(i)));
        }
        const double feed = path.feed(i);
        if (!std::isfinite(feed) || feed < 0.0) {
            return makeError(ErrorCode::Geometry, "invalid feed " + std::to_string(feed) +
                                                      " mm/s at " + recordName(i, path.line(i)));
        }
        if (feed > 0.0 && (feedRuns.empty() || feed != feedRuns.back())) {
            feedRuns.push_back(feed);
        }
    }
    return {};
}

// The one constant feed of the analysis (see AxisProfileOptions::feedOverride). feeds: the
// positive programmed feeds, a run of one feed once (validateInput).
Result<double> chooseFeed(const PathSamples& path, double feedOverride, std::vector<double> feeds) {
    if (feedOverride > 0.0) {
        return feedOverride;
    }
    if (feeds.empty()) {
        return makeError(ErrorCode::InvalidArgument,
                         "no programmed feed in the program: give a feed override");
    }
    if (std::all_of(feeds.begin(), feeds.end(), [&](double f) { return f == feeds.front(); })) {
        return feeds.front();
    }
    // Varying feeds: the median over records, not over runs, so every record counts once.
    feeds.clear();
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path.feed(i) > 0.0) {
            feeds.push_back(path.feed(i));
        }
    }
    const std::size_t mid = feeds.size() / 2;
    std::nth_element(feeds.begin(), feeds.begin() + mid, feeds.end());
    double median = feeds[mid];
    if (feeds.size() % 2 == 0) {
        median = 0.5 * (median + *std::max_element(feeds.begin(), feeds.begin() + mid));
    }
    return median;
}

// Fills pathParameter, time and sampleRecord; drops points closer than kMinPathStepMm to the last
// kept one (distance to the kept point, so creeping sub-threshold steps still add up).
void buildPathParameter(const PathSamples& path, const AxisProfileOptions& options,
                        AxisProfile& profile) {
    const bool centre = options.feedReference == FeedReference::Centre;
    const double radius = options.toolRadius;
    auto pointOf = [&](std::size_t i) -> Vec3 {
        return centre ? Vec3(path.tip(i) + radius * path.toolAxis(i)) : path.tip(i);
    };
    const bool timed = options.blockTimes && !centre;
    profile.pathParameter.reserve(path.size());
    profile.sampleRecord.reserve(path.size());
    const auto addSample = [&](double s, std::size_t record) {
        profile.pathParameter.push_back(s);
        profile.sampleRecord.push_back(static_cast<RecordIndex>(record));
    };
    Vec3 last = pointOf(0);
    double s = 0.0, length = 0.0;
    addSample(0.0, 0);
    for (std::size_t i = 1; i < path.size(); ++i) {
        const Vec3 p = pointOf(i);
        const double step = (p - last).norm();
        if (!(step >= kMinPathStepMm)) {
            ++profile.mergedDuplicates;
            continue;
        }
        // A merged record's block time is carried by the next kept one: its chord is measured
        // from the last kept point, and the feed of the block that ends there times it.
        const double feed = path.feed(i);
        s += timed && feed > 0.0 ? step * profile.feed / feed : step;
        length += step;
        last = p;
        addSample(s, i);
    }
    profile.pathLength = length;
}

// One machine axis at the samples, gathered for its differentiation only.
std::span<const double> sampledAxis(std::span<const kinematics::MachineAxes> axes,
                                    std::span<const RecordIndex> sampleRecord,
                                    kinematics::AxisId id, std::vector<double>& values) {
    values.resize(sampleRecord.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = axes[sampleRecord[i]][id];
    }
    return values;
}

} // namespace

Result<AxisProfile> analyseAxisMotion(SharedMachineAxes sharedAxes, const PathSamples& path,
                                      const AxisProfileOptions& options) {
    if (!sharedAxes) {
        return makeError(ErrorCode::InvalidArgument, "axis motion: no machine axes");
    }
    const std::span<const kinematics::MachineAxes> axes = *sharedAxes;
    std::vector<double> feedRuns;
    if (Status ok = validateInput(axes, path, options, feedRuns); !ok) {
        return std::unexpected(std::move(ok.error()));
    }
    const Result<double> feed = chooseFeed(path, options.feedOverride, std::move(feedRuns));
    if (!feed) {
        return std::unexpected(feed.error());
    }
    AxisProfile profile;
    profile.recordAxes = std::move(sharedAxes);
    profile.feed = *feed;
    profile.feedReference = options.feedReference;
    profile.method = options.method;
    profile.filterSeconds = options.filterSeconds;
    buildPathParameter(path, options, profile);
    if (path.posesRead) {
        path.posesRead();
    }
    profile.cycleTime = profile.pathParameter.back() / profile.feed;
    if (Status going = checkCancelled(options.cancel); !going) {
        return std::unexpected(std::move(going.error()));
    }
    const std::size_t n = profile.pathParameter.size();
    std::vector<std::size_t> knots;
    if (options.method == DerivativeMethod::Spline) {
        knots = motionKnots(profile.pathParameter, axes, profile.sampleRecord);
        profile.mergedShortChords = n - knots.size();
        // Every sample a knot is the differentiation's default: the same spline, without 8
        // bytes per sample held through the fits.
        if (knots.size() == n) {
            freeStorage(knots);
        }
    }
    // The reversals are audited over every record's A (without merged samples those are the
    // samples' A) before the derivatives, so that no axis's positions outlive its own fit.
    {
        std::vector<double> a(axes.size());
        std::transform(axes.begin(), axes.end(), a.begin(),
                       [](const kinematics::MachineAxes& m) { return m.a; });
        profile.aReversals = auditReversals(a);
    }
    if (Status going = checkCancelled(options.cancel); !going) {
        return std::unexpected(std::move(going.error()));
    }
    // Each axis's positions are gathered for its own differentiation and dropped after it.
    const PositionsOf positionsOf = [&](std::size_t k, std::vector<double>& scratch) {
        return sampledAxis(axes, profile.sampleRecord, kinematics::kAllAxes[k], scratch);
    };
    std::vector<Result<AxisSeries>> series =
        differentiateAxes(profile.pathParameter, kinematics::kAllAxes.size(), positionsOf,
                          profile.feed, options.method, options.filterSeconds, knots,
                          options.cancel, options.filterSeriesBytesAtOnce);
    // The axes skipped on cancellation hold Cancelled: the job's, not an error of theirs.
    if (Status going = checkCancelled(options.cancel); !going) {
        return std::unexpected(std::move(going.error()));
    }
    for (kinematics::AxisId id : kinematics::kAllAxes) {
        Result<AxisSeries>& axis = series[static_cast<int>(id)];
        if (!axis) {
            Error error = std::move(axis.error());
            error.message = std::string("axis ") + kinematics::axisName(id) + ": " + error.message;
            return std::unexpected(std::move(error));
        }
        profile.axes[static_cast<int>(id)] = std::move(*axis);
    }
    return profile;
}

Result<AxisProfile> analyseAxisMotion(std::span<const kinematics::MachineAxes> axes,
                                      const PathSamples& path, const AxisProfileOptions& options) {
    return analyseAxisMotion(
        std::make_shared<const std::vector<kinematics::MachineAxes>>(axes.begin(), axes.end()),
        path, options);
}

std::vector<double> AxisSeries::velocities(std::size_t n) const {
    return still() ? std::vector<double>(n, 0.0) : velocity;
}

std::vector<double> AxisSeries::accelerations(std::size_t n) const {
    return still() ? std::vector<double>(n, 0.0) : acceleration;
}

std::vector<double> AxisProfile::positions(kinematics::AxisId id) const {
    std::vector<double> values;
    if (!sampleRecord.empty() && recordAxes) { // none without samples, or once released
        sampledAxis(*recordAxes, sampleRecord, id, values);
    }
    return values;
}

void AxisProfile::releaseSampleData() {
    releasedSampleCount = sampleCount();
    for (AxisSeries& series : axes) {
        freeStorage(series.velocity);
        freeStorage(series.acceleration);
    }
    freeStorage(pathParameter);
    freeStorage(sampleRecord);
    recordAxes.reset();
    sampleDataReleased = true;
}

std::vector<double> AxisProfile::times() const {
    std::vector<double> seconds(pathParameter.size());
    for (std::size_t i = 0; i < seconds.size(); ++i) {
        seconds[i] = timeAt(i);
    }
    return seconds;
}

namespace {
constexpr std::pair<const char*, DerivativeMethod> kDerivativeMethodNames[] = {
    {"spline", DerivativeMethod::Spline},
    {"raw-spline", DerivativeMethod::RawSpline},
    {"fd", DerivativeMethod::FiniteDifference},
    {"filter", DerivativeMethod::Filtered},
};
} // namespace

const char* nameOf(DerivativeMethod method) {
    for (const auto& [name, value] : kDerivativeMethodNames) {
        if (value == method) {
            return name;
        }
    }
    return "filter";
}

std::optional<DerivativeMethod> derivativeMethodNamed(std::string_view name) {
    for (const auto& [key, method] : kDerivativeMethodNames) {
        if (name == key) {
            return method;
        }
    }
    return std::nullopt;
}

} // namespace bladeaxis::analysis
