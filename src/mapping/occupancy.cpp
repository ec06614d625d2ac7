#include "ussnav/mapping/occupancy.hpp"

#include <cmath>
#include <limits>

namespace ussnav {

RayHit castRay(const OccupancyMap& map, const Vec3& from, const Vec3& to, bool unknown_blocks) {
  RayHit hit;
  const double res = map.resolution();
  const Vec3 d = to - from;
  const double len = d.norm();
  hit.point = to;
  hit.distance = len;
  if (len < 1e-12) return hit;
  const Vec3 dir = d / len;
  Vec3i key = map.keyOf(from);
  const Vec3i end = map.keyOf(to);
  Vec3i step;
  Vec3 t_max, t_delta;
  for (int i = 0; i < 3; ++i) {
    if (dir[i] > 0) {
      step[i] = 1;
      t_max[i] = ((key[i] + 1) * res - from[i]) / dir[i];
      t_delta[i] = res / dir[i];
    } else if (dir[i] < 0) {
      step[i] = -1;
      t_max[i] = (key[i] * res - from[i]) / dir[i];
      t_delta[i] = -res / dir[i];
    } else {
      step[i] = 0;
      t_max[i] = std::numeric_limits<double>::infinity();
      t_delta[i] = std::numeric_limits<double>::infinity();
    }
  }
  const int max_steps = int(std::ceil(len / res)) * 3 + 3;
  for (int s = 0; s < max_steps && key != end; ++s) {
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    const double t = t_max[axis];
    if (t > len) break;
    key[axis] += step[axis];
    t_max[axis] += t_delta[axis];
    const VoxelState st = map.state(key);
    if (st == VoxelState::Occupied || (unknown_blocks && st == VoxelState::Unknown)) {
      hit.blocked = true;
      hit.hit_state = st;
      hit.distance = t;
      hit.point = from + dir * t;
      return hit;
    }
  }
  return hit;
}

bool isSafe(const OccupancyMap& map, const Vec3& p, double radius, bool unknown_unsafe) {
  const double res = map.resolution();
  const Vec3i c = map.keyOf(p);
  const int n = int(std::ceil(radius / res));
  for (int dz = -n; dz <= n; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        // Distance from p to the nearest point of voxel k.
        const Vec3 lo = k.cast<double>() * res, hi = lo + Vec3::Constant(res);
        const Vec3 q = p.cwiseMax(lo).cwiseMin(hi);
        if ((q - p).norm() > radius) continue;
        const VoxelState st = map.state(k);
        if (st == VoxelState::Occupied || (unknown_unsafe && st == VoxelState::Unknown)) return false;
      }
  return true;
}

}  // namespace ussnav
