#pragma once
// Machine-axis motion along a posted program at constant feed (spec §8.1-8.2): path parameter,
// time, per-axis velocity / acceleration / jerk with peaks and 99.9th percentiles, and the A
// reversal audit (spec §6.4). Units: mm, rad, s; linear axes mm/s..., rotary rad/s....

#include "core/analysis/reversals.h"
#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/kinematics/machine_model.h"
#include "core/toolpath/toolpath.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace bladeaxis::analysis {

// Consecutive samples closer than this along the path (mm) are merged: the spline and the
// differences need a strictly increasing path parameter.
constexpr double kMinPathStepMm = 1e-9;

// What the feed moves (spec §8.1): the tool tip (NC convention with tool-centre-point control)
// or the cutter centre Q = O + R V (then A'' = theta''(S) F^2 exactly for re-scheduled paths).
enum class FeedReference { Tip, Centre };

// Filtered (the default, docs/figures.md): the figures of a controller that runs the program at
// the one constant feed of the analysis and smooths each axis over filterSeconds (8 ms): the
// axis resampled every millisecond at that feed, smoothed by a centred moving average applied
// twice (a triangular FIR, spec §8.1), differentiated by central differences; peaks and 99.9th
// percentiles over the millisecond series. It does not depend on how the post spaced the points
// (a micrometre chord on the straight move changes no figure) nor on block-to-block ripple
// shorter than the window, which such a controller does not follow.
// Spline: a not-a-knot cubic spline of each axis over s through the samples that carry motion
// (motionKnots: micrometre chords on a straight move are merged), evaluated at every sample: the
// motion of a controller that follows every block exactly; block-to-block ripple of the tip's
// chords shows in it in full. RawSpline: the same spline through every sample (spec §8.1's
// headline method; a 2 um chord moves its peaks by tens of per cent). FiniteDifference: raw
// 3-point differences (they mostly measure the CL discretisation).
enum class DerivativeMethod { Spline, RawSpline, FiniteDifference, Filtered };

// The names of the methods on the command line (--derivatives) and in job files: "spline",
// "raw-spline", "fd", "filter".
const char* nameOf(DerivativeMethod method);
std::optional<DerivativeMethod> derivativeMethodNamed(std::string_view name);

struct AxisProfileOptions {
    FeedReference feedReference = FeedReference::Tip;
    DerivativeMethod method = DerivativeMethod::Filtered;
    // mm/s. 0 = the programmed feed. The analysis is always at ONE constant feed (peak ratios
    // between methods are then F-free, spec §8.1); when the programmed feeds vary, that feed is
    // the median of the positive programmed feeds (rapids and unknown feeds, stored as 0, are
    // ignored). A per-record feed would add impulsive accelerations at every feed step, which
    // measure the post-processor, not the tool orientation.
    double feedOverride = 0.0;
    // The records' feeds are the program's block timing (G93 inverse time: each block lasts
    // 1/F whatever its length, and the reader turns that into the tip speed of the block). Then
    // the path parameter advances by F x the block's time instead of its tip chord, so every
    // figure, T1 and T2 describe the motion as the program times it (a re-scheduled block with
    // the same F but a new tip chord has a new tip speed). Tip feed reference only; the reported
    // path length stays the tip's.
    bool blockTimes = false;
    double toolRadius = 0.0; // mm, required (> 0) for FeedReference::Centre
    // Moving-average window of DerivativeMethod::Filtered, s: the smoothing time of the
    // controller the default figures assume.
    double filterSeconds = 0.008;
    // Polled between the analysis's stages and before each axis's derivatives: a cancelled
    // analysis ends with ErrorCode::Cancelled within one axis's differentiation (about 0.3 s
    // at five million records). None: the analysis runs to its end.
    const CancelToken* cancel = nullptr;
    // The most bytes the filter's millisecond series (8 per millisecond of the pass and axis)
    // may hold at once; above it the axes are differentiated one at a time. 0: no limit, the
    // axes on every thread of the context. A caller that owns a memory bound sets it (a job).
    double filterSeriesBytesAtOnce = 0.0;
};

// One machine axis. Derivatives are time derivatives at the constant feed F:
// velocity = q'(s) F, acceleration = q''(s) F^2, jerk = q'''(s) F^3. The jerk is kept as its
// peak only: nothing reads it per sample, and on a million-record program each of a job's two
// profiles would hold 40 MB of it. Nor are the positions: they are the machine axes the profile
// was made from (AxisProfile::position).
struct AxisSeries {
    // At the samples; both empty for a still axis (B in four-axis work), whose derivatives are
    // all zero: its zeros were 16 bytes per sample in each profile a job holds.
    std::vector<double> velocity, acceleration;
    double minPosition = 0.0, maxPosition = 0.0; // the range of the positions at the samples
    // max |.| over the samples, and for the spline method also over 4 interior points per
    // interval (q'' is linear and q''' constant per interval, so only the velocity can peak
    // inside an interval; the other two peaks are attained at the samples).
    double peakVelocity = 0.0, peakAcceleration = 0.0, peakJerk = 0.0;
    // 99.9th percentile of |.| at the samples (linear interpolation between order statistics).
    double p999Velocity = 0.0, p999Acceleration = 0.0;

    bool still() const { return velocity.empty(); }
    double velocityAt(std::size_t i) const { return still() ? 0.0 : velocity[i]; }
    double accelerationAt(std::size_t i) const { return still() ? 0.0 : acceleration[i]; }
    // Every sample's velocity or acceleration (a still axis's zeros), for a plot: n samples.
    std::vector<double> velocities(std::size_t n) const;
    std::vector<double> accelerations(std::size_t n) const;
};

// The index of a record in the records an analysis reads: 32 bits, half the bytes of a size_t
// in every sample of a profile. A program text is at most 4 GiB (io/), so its records are
// fewer than 2^32.
using RecordIndex = std::uint32_t;

// The machine axes of a program's records, shared by whoever made them (a job's pass, the
// re-scheduled pass) and the profiles analysed from them.
using SharedMachineAxes = std::shared_ptr<const std::vector<kinematics::MachineAxes>>;

struct AxisProfile {
    std::vector<double> pathParameter;     // s, mm, strictly increasing, s[0] = 0
    std::vector<RecordIndex> sampleRecord; // input record of each sample (merged ones dropped)
    // The machine axes of every record analysed, A continuous; sampleRecord indexes them. The
    // positions at the samples are read from them rather than copied per axis: the copies were
    // 40 bytes per sample in each profile a job holds.
    SharedMachineAxes recordAxes;
    std::array<AxisSeries, 5> axes; // X Y Z A B, index by kinematics::AxisId
    // A reversals over ALL input records (indices are record indices): a rotation at a fixed
    // point, merged away for the derivatives, still turns the axis.
    ReversalAudit aReversals;
    double pathLength = 0.0;           // mm
    double feed = 0.0;                 // mm/s used
    double cycleTime = 0.0;            // s at that constant feed
    std::size_t mergedDuplicates = 0;  // samples dropped because ds < kMinPathStepMm
    std::size_t mergedShortChords = 0; // samples off the spline's knots (DerivativeMethod::Spline)
    FeedReference feedReference = FeedReference::Tip; // which arc length s is (report it)
    DerivativeMethod method = DerivativeMethod::Filtered;
    double filterSeconds = 0.008; // the smoothing time of DerivativeMethod::Filtered, s

    const AxisSeries& axis(kinematics::AxisId id) const { return axes[static_cast<int>(id)]; }

    // The position of an axis at sample i (mm or rad): its record's machine axis.
    double position(kinematics::AxisId id, std::size_t i) const {
        return (*recordAxes)[sampleRecord[i]][id];
    }
    // Every sample's position of an axis, for a plot or a reversal count (none once the
    // sample data are released).
    std::vector<double> positions(kinematics::AxisId id) const;

    // The time of sample i at the constant feed, s: t = s / F. Computed, not kept: 8 bytes per
    // sample of each profile a job holds.
    double timeAt(std::size_t i) const { return pathParameter[i] / feed; }
    // Every sample's time, for a plot's axis.
    std::vector<double> times() const;

    // True once releaseSampleData freed the per-sample data.
    bool sampleDataReleased = false;
    // The number of samples: the path parameter's, kept once it is released.
    std::size_t sampleCount() const {
        return sampleDataReleased ? releasedSampleCount : pathParameter.size();
    }
    // Frees every per-sample array: each axis's velocity and acceleration (16 bytes per sample
    // and moving axis), the samples' path parameter and records (12), and gives up the
    // profile's share of the machine axes (recordAxes). It keeps the figures (peaks,
    // percentiles, ranges, reversals, lengths, times) and the sample count: for a holder that
    // has read the samples for the last time (a batch job once the input's T2, lost motion and
    // layers' motion are taken). Every axis then reads as still and the positions and times as
    // none: nothing that reads samples (T2, lost motion, axes.csv, a plot, a layer's peaks, the
    // comparison) may be given the profile afterwards.
    void releaseSampleData();
    std::size_t releasedSampleCount = 0; // sampleCount() once released
};

// The tool path an analysis reads: a program's records, or new tool poses over them. A
// re-scheduled pass keeps each record's ball centre, feed and source line and has new tool
// axes (and so new tips); when the written program times its blocks anew, its feeds too.
// Lending the new poses this way spares a copy of every record (104 bytes each) for the
// analysis of the new motion.
struct PathSamples {
    std::span<const toolpath::ClRecord> records;
    std::span<const Vec3> toolAxes = {}; // empty: the records' tool axes
    // Required (> 0) with toolAxes: the radius (mm) of the records' ball centres the new poses
    // keep, whose tips are then tipOfBall(centre, toolAxes[i], R).
    double keptCentreRadius = 0.0;
    std::span<const double> feeds = {}; // empty: the records' feeds (mm/s)
    // Called once the analysis has read the tips, tool axes and feeds for the last time (its
    // path parameter is made), so that a lender that needs its poses no more can free them
    // before the derivatives are taken. The records' lines may still be read.
    std::function<void()> posesRead = {};

    std::size_t size() const { return records.size(); }
    Vec3 tip(std::size_t i) const {
        return toolAxes.empty() ? records[i].tip
                                : tipOfBall(toolpath::ballCentre(records[i], keptCentreRadius),
                                            toolAxes[i], keptCentreRadius);
    }
    const Vec3& toolAxis(std::size_t i) const {
        return toolAxes.empty() ? records[i].axis : toolAxes[i];
    }
    double feed(std::size_t i) const { return feeds.empty() ? records[i].feed : feeds[i]; }
    int line(std::size_t i) const { return records[i].line; }
};

// axes: machine axes per record (A already continuous: see unwrapRotary for modulo programs),
// of which the profile keeps a share; path: tip and tool axis per record (for s) and the
// programmed feeds. Errors also when the poses or feeds lent in `path` are not one per record.
// Errors: InvalidArgument (sizes differ, empty input, more records than a RecordIndex counts,
// no usable feed, bad options), Geometry (a non-finite coordinate, axis value or feed, named
// with its record index and source line).
// A single sample (one record, or all records merged) gives zero derivatives.
Result<AxisProfile> analyseAxisMotion(SharedMachineAxes axes, const PathSamples& path,
                                      const AxisProfileOptions& options);

// The same on a copy of `axes`, which the profile keeps.
Result<AxisProfile> analyseAxisMotion(std::span<const kinematics::MachineAxes> axes,
                                      const PathSamples& path, const AxisProfileOptions& options);

// The analysis of a program's own records.
inline Result<AxisProfile> analyseAxisMotion(std::span<const kinematics::MachineAxes> axes,
                                             std::span<const toolpath::ClRecord> records,
                                             const AxisProfileOptions& options) {
    return analyseAxisMotion(axes, PathSamples{.records = records}, options);
}

} // namespace bladeaxis::analysis
