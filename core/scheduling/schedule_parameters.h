#pragma once
// Every tunable of the scheduling engine (spec Appendix A), units in the names, and the two
// presets. Faithful = the paper's rules where the paper has one; Best = corrected/extended
// defaults (exact epsilon, automatic lead fraction, graph-limit corners).

#include "core/base/error.h"
#include "core/base/units.h"

namespace bladeaxis::scheduling {

enum class Preset { Faithful, Best };
enum class BasePointRule { Exit, Entry };        // spec §1.7
enum class Visibility { Local, Global };         // spec §2.4
enum class LeadMode { Fixed, Auto };             // spec §3.4
enum class KeyMode { Both, Worst };              // spec §4.3
enum class Adjust { Recursive, Shift };          // spec §4.5
enum class EpsilonRule { Paper, Exact };         // spec §5.4
enum class CornerForm { Euclidean, GraphLimit }; // spec §5.2 / §5.5 (Euclidean in rad and mm)
// [X] The curvature profile of a graph-limit corner: the paired cubics of §5 (theta'' a bump,
// 8/3 x the least peak for the slope change over the span, §5.6) or the plateau theta'' =
// A (1 - v^4), v = (S - S2) / W, a sextic in S (1.25 x the least peak, still G2).
enum class CornerProfile { Bezier, Plateau };

struct ScheduleParameters {
    Preset preset = Preset::Best;

    // §2.3: both limits rotate inward by taper + safety angle.
    double taperHalfAngleRad = 0.0;
    double safetyAngleRad = 0.0;

    // §1.5: tangent chord l_t = max(tangentChordMinMm, tangentChordMedianFactor * median chord).
    double tangentChordMinMm = 0.5;
    double tangentChordMedianFactor = 3.0;

    // §1.6: window w = max(curvatureWindowMinMm, fraction * revolution length), hysteresis,
    // merge gap L_gap = concaveGapToolRadii * R, minimum run L_min = max(k R, fraction * rev).
    double curvatureWindowMinMm = 2.0;
    double curvatureWindowRevolutionFraction = 0.01;
    double curvatureHysteresisPerMm = 1e-4;
    double concaveGapToolRadii = 2.0;
    double concaveMinRunToolRadii = 2.0;
    double concaveMinRunRevolutionFraction = 0.03;
    BasePointRule basePoint = BasePointRule::Exit;

    // §2.4 (optional narrowing, off = local rule of the paper). The lead band [X] intersects the
    // channel with theta_n + [min, max], theta_n the outward surface normal angle (taken normal
    // to the centre curve, whose tangent is the chord bisector of §1.5).
    Visibility visibility = Visibility::Local;
    bool leadBand = false;
    double leadBandMinRad = units::degToRad(-30.0);
    double leadBandMaxRad = units::degToRad(30.0);

    // §2.5: margin m before the monotone hull; §4.6 optional despiking (non-conservative).
    double marginRad = units::degToRad(3.0);
    bool despike = false;
    // §2.5: a layer without a monotone path keeps its original orientation (false), or gets the
    // original projected onto the raw channel and smoothed, reversals allowed (true).
    bool allowNonmonotone = false;

    // §3.4: lead-in/out fraction rho (fixed) or golden-section search over [min, max] (auto).
    LeadMode leadMode = LeadMode::Auto;
    double leadFraction = 0.15;
    double leadSearchMinFraction = 0.02;
    double leadSearchMaxFraction = 0.45;
    int leadSearchEvaluations = 20;

    // §4: key point insertion and feasibility tolerance (rad).
    KeyMode keyMode = KeyMode::Both;
    double keyToleranceRad = 1e-9;
    // §4.5: crossings resolved by recursion only, or first by shifting the key inward.
    Adjust adjust = Adjust::Recursive;

    // §5: corner construction, epsilon rule, final clearance (rad), bisection effort.
    EpsilonRule epsilonRule = EpsilonRule::Exact;
    CornerForm cornerForm = CornerForm::GraphLimit;
    CornerProfile cornerProfile = CornerProfile::Plateau; // graph-limit corners only
    double finalClearanceRad = 0.0;
    int epsilonBisectionSteps = 40;
    int curveChecksPerCubic = 64;

    // The job's thread count (0 = every hardware thread): read only by the job pipeline, which
    // sets it as the execution context of the job (core/base/execution.h). The scheduling
    // itself runs on the context's threads and never reads it.
    unsigned threads = 0;
};

// Paper rules: epsilon0 rule (§3.2 of [L], corrected Eq. 13), fixed rho = 0.15, Euclidean
// corners in the rad/mm plane, both key points per guidance line.
ScheduleParameters faithfulPreset();
// Recommended: exact epsilon by bisection, automatic rho, graph-limit plateau corners.
ScheduleParameters bestPreset();

// Checks every parameter against its domain; the message names the parameter and value.
Status validateParameters(const ScheduleParameters& parameters);

} // namespace bladeaxis::scheduling
