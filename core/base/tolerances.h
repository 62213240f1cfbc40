#pragma once
// Named tolerances used across modules. Units in the names.

namespace bladeaxis::tol {

// Consecutive cutter centres closer than this are merged (spec §1.2).
constexpr double kDuplicatePointMm = 1e-6;
// A unit vector must have |v| = 1 within this after normalisation.
constexpr double kUnitLength = 1e-12;
// Input vectors shorter than this cannot be normalised: an error.
constexpr double kZeroVector = 1e-12;
// Round trips of written numbers (files carry at most ~1e-9 relative precision).
constexpr double kRoundTripMm = 1e-9;
// An A step larger than this counts towards a direction reversal (spec §6.4).
constexpr double kReversalStepRad = 1e-6;
// Constant-B check of the input (spec §1.2).
constexpr double kConstantTiltRad = 1e-6;

} // namespace bladeaxis::tol
