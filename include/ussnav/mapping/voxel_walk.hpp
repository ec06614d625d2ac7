#pragma once
// Header templates behind castRay/isSafe, parameterised on the voxel-state lookup so that the
// RollingGrid runs them on its non-virtual ring-buffer lookup and OccupancyMap on the virtual
// one, with one implementation. Cost: O(voxels crossed) for a ray, O((r/res)^3) for a sphere.

#include <cmath>
#include <cstdlib>
#include <limits>

#include "ussnav/mapping/occupancy.hpp"

namespace ussnav::detail {

// Amanatides-Woo walk from `from` to `to` in voxels of size `res`. The walk takes exactly
// |end - start| steps per axis, so it always ends in the voxel of `to` whatever the rounding.
// `state(key)` returns the VoxelState of a key. The start voxel is not tested. Where the segment
// passes exactly through a voxel edge or corner (two axes' boundaries at the same point, as
// between voxel centres at slopes like 1:5), the voxels on both sides of it are tested: a walk
// stepping one axis first would slip between two blocking voxels that touch only diagonally, and
// which of the two it steps first depends on the start point's rounding (a flight path judged
// free from one point of a line and blocked from the next held a UAV in place for 270 s).
inline constexpr double kCornerEps = 1e-9;  // segment parameter: boundaries this close are crossed at once

template <class StateFn>
RayHit walkSegment(double res, const Vec3& from, const Vec3& to, bool unknown_blocks,
                   StateFn&& state) {
  RayHit hit;
  hit.point = to;
  const Vec3 d = to - from;
  const double len = d.norm();
  hit.distance = len;
  if (!(len > 1e-12)) return hit;
  const Vec3 u = from / res, v = to / res;
  Vec3i key(int(std::floor(u.x())), int(std::floor(u.y())), int(std::floor(u.z())));
  const Vec3i end(int(std::floor(v.x())), int(std::floor(v.y())), int(std::floor(v.z())));
  const double inf = std::numeric_limits<double>::infinity();
  int step[3], remaining[3];
  double t_max[3], t_delta[3];  // in units of the segment parameter t in [0, 1]
  for (int i = 0; i < 3; ++i) {
    remaining[i] = std::abs(end[i] - key[i]);
    step[i] = end[i] > key[i] ? 1 : -1;
    if (remaining[i] == 0) {
      t_max[i] = t_delta[i] = inf;
      continue;
    }
    const double ad = std::max(std::abs(v[i] - u[i]), 1e-12);
    t_delta[i] = 1.0 / ad;
    t_max[i] = (step[i] > 0 ? (key[i] + 1 - u[i]) : (u[i] - key[i])) * t_delta[i];
  }
  const int total = remaining[0] + remaining[1] + remaining[2];
  // Whether voxel k, entered at segment parameter t, stops the walk (then `hit` says where).
  auto stops = [&](const Vec3i& k, double t) {
    const VoxelState st = state(k);
    if (st != VoxelState::Occupied && !(unknown_blocks && st == VoxelState::Unknown)) return false;
    hit.blocked = true;
    hit.hit_state = st;
    hit.distance = t * len;
    hit.point = from + d * t;
    return true;
  };
  for (int s = 0; s < total; ++s) {
    const int axis = t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
    const double t = std::min(t_max[axis], 1.0);
    // t_max[axis] is the least, and an axis with no steps left has t_max = inf: two compares
    // tell an edge or corner crossing from the usual face crossing.
    const int a1 = axis == 0 ? 1 : 0, a2 = axis == 2 ? 1 : 2;
    const double tm = t_max[axis] + kCornerEps;
    if (t_max[a1] <= tm || t_max[a2] <= tm) {
      for (const int b : {a1, a2}) {  // an edge or corner crossed: the side voxels too
        if (t_max[b] > tm) continue;
        Vec3i side = key;
        side[b] += step[b];
        if (stops(side, t)) return hit;
      }
    }
    key[axis] += step[axis];
    t_max[axis] = --remaining[axis] == 0 ? inf : t_max[axis] + t_delta[axis];
    if (stops(key, t)) return hit;
  }
  return hit;
}

// True when no voxel whose box comes within `radius` of p is Occupied (or Unknown when
// `unknown_unsafe`).
template <class StateFn>
bool sphereIsSafe(double res, const Vec3& p, double radius, bool unknown_unsafe, StateFn&& state) {
  const Vec3i c(int(std::floor(p.x() / res)), int(std::floor(p.y() / res)), int(std::floor(p.z() / res)));
  const int n = int(std::ceil(radius / res));
  const double r2 = radius * radius;
  for (int dz = -n; dz <= n; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        const Vec3 lo = k.cast<double>() * res, hi = lo + Vec3::Constant(res);
        if ((p.cwiseMax(lo).cwiseMin(hi) - p).squaredNorm() > r2) continue;
        const VoxelState st = state(k);
        if (st == VoxelState::Occupied || (unknown_unsafe && st == VoxelState::Unknown)) return false;
      }
  return true;
}

}  // namespace ussnav::detail
