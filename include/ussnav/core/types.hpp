#pragma once
// Basic geometric types shared by every stage: Eigen aliases and the UAV pose.
// The world frame is ENU-like: x east, y north, z up, metres; yaw about +z, radians.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>

namespace ussnav {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Vec3i = Eigen::Vector3i;
using Mat3 = Eigen::Matrix3d;
using Iso3 = Eigen::Isometry3d;

// A flying pose: position and heading. The camera looks along +x of the body frame.
struct Pose {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;

  Iso3 toIsometry() const {
    Iso3 t = Iso3::Identity();
    t.translation() = position;
    t.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
    return t;
  }
};

// Axis-aligned box, used for bounds everywhere.
struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  static Aabb of(const Vec3& lo, const Vec3& hi) {
    Aabb b;
    b.min = lo;
    b.max = hi;
    return b;
  }
  bool empty() const { return (min.array() > max.array()).any(); }
  void extend(const Vec3& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  void extend(const Aabb& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
  bool contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  Vec3 center() const { return 0.5 * (min + max); }
};

constexpr double kPi = 3.14159265358979323846;
inline double deg2rad(double d) { return d * kPi / 180.0; }
inline double rad2deg(double r) { return r * 180.0 / kPi; }
// Wraps an angle to (-pi, pi].
inline double wrapAngle(double a) {
  while (a > kPi) a -= 2 * kPi;
  while (a <= -kPi) a += 2 * kPi;
  return a;
}

}  // namespace ussnav
