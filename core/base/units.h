#pragma once
// Units convention: inside the program lengths are mm, angles rad, time s.
// Degrees, inches and mm/min appear only at the edges (files, command line, GUI) and are
// converted with these functions, in one place.

#include <numbers>

namespace bladeaxis::units {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMmPerInch = 25.4;
constexpr double kSecondsPerMinute = 60.0;

constexpr double degToRad(double degrees) {
    return degrees * (kPi / 180.0);
}
constexpr double radToDeg(double radians) {
    return radians * (180.0 / kPi);
}
constexpr double inchToMm(double inches) {
    return inches * kMmPerInch;
}
constexpr double mmToInch(double mm) {
    return mm / kMmPerInch;
}
// Feed words are mm/min (or inch/min); the core works in mm/s.
constexpr double perMinuteToPerSecond(double perMinute) {
    return perMinute / kSecondsPerMinute;
}
constexpr double perSecondToPerMinute(double perSecond) {
    return perSecond * kSecondsPerMinute;
}

} // namespace bladeaxis::units
