#include "ussnav/mapping/occupancy.hpp"

#include "ussnav/mapping/voxel_walk.hpp"

namespace ussnav {

RayHit castRay(const OccupancyMap& map, const Vec3& from, const Vec3& to, bool unknown_blocks) {
  return detail::walkSegment(map.resolution(), from, to, unknown_blocks,
                             [&](const Vec3i& k) { return map.state(k); });
}

bool isSafe(const OccupancyMap& map, const Vec3& p, double radius, bool unknown_unsafe) {
  return detail::sphereIsSafe(map.resolution(), p, radius, unknown_unsafe,
                              [&](const Vec3i& k) { return map.state(k); });
}

}  // namespace ussnav
