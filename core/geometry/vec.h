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

} // namespace bladeaxis
