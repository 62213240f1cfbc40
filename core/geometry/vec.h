#pragma once
// Geometry vocabulary: Eigen-based vectors. Lengths in mm, angles in rad.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bladeaxis {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Rotation matrices about the coordinate axes, right-handed, angle in rad.
inline Mat3 rotationX(double angle) {
    return Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix();
}
inline Mat3 rotationY(double angle) {
    return Eigen::AngleAxisd(angle, Vec3::UnitY()).toRotationMatrix();
}
inline Mat3 rotationZ(double angle) {
    return Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
}

inline bool isFinite(const Vec3& v) {
    return v.allFinite();
}

// O = Q - R V: the tip of a ball-end tool of radius R whose ball centre is Q, for the tool axis
// V. A re-scheduled pose keeps its ball centre, so its tip is made from the centre whenever it
// is read (nothing keeps the tips of a schedule), always with this arithmetic: the same bits.
inline Vec3 tipOfBall(const Vec3& centre, const Vec3& axis, double radius) {
    return centre - radius * axis;
}

} // namespace bladeaxis
