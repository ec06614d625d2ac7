#pragma once
// The read-only occupancy interface that later stages (skeleton, frontiers, planning) use,
// so they work on the RollingGrid and on hand-made test grids alike (an adaptor, as in
// nanoflann). Voxels are globally aligned: the voxel key of point p is floor(p / resolution).

#include <cmath>
#include <cstdint>

#include "ussnav/core/types.hpp"

namespace ussnav {

enum class VoxelState : uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

class OccupancyMap {
 public:
  virtual ~OccupancyMap() = default;
  virtual double resolution() const = 0;
  // State of voxel `key`; Unknown outside the map's current window.
  virtual VoxelState state(const Vec3i& key) const = 0;
  // Whether `key` is inside the window the map currently holds.
  virtual bool inWindow(const Vec3i& key) const = 0;
  // World-frame bounds of the current window.
  virtual Aabb window() const = 0;

  Vec3i keyOf(const Vec3& p) const {
    const double r = resolution();
    return Vec3i(int(std::floor(p.x() / r)), int(std::floor(p.y() / r)), int(std::floor(p.z() / r)));
  }
  Vec3 centerOf(const Vec3i& k) const { return (k.cast<double>() + Vec3::Constant(0.5)) * resolution(); }
  VoxelState stateAt(const Vec3& p) const { return state(keyOf(p)); }
};

// Result of walking a segment through the voxels.
struct RayHit {
  bool blocked = false;        // stopped before reaching the end
  VoxelState hit_state = VoxelState::Free;  // state of the blocking voxel
  Vec3 point = Vec3::Zero();   // where it stopped: entry point of the blocking voxel, or `to`
  double distance = 0.0;       // from `from` to `point`
};

// Walks from `from` to `to` (Amanatides-Woo DDA). Occupied voxels block; Unknown voxels block
// when `unknown_blocks`. The start voxel is not tested.
RayHit castRay(const OccupancyMap& map, const Vec3& from, const Vec3& to, bool unknown_blocks);

// True when no voxel between a and b blocks (see castRay).
inline bool lineOfSight(const OccupancyMap& map, const Vec3& a, const Vec3& b, bool unknown_blocks) {
  return !castRay(map, a, b, unknown_blocks).blocked;
}

// True when every voxel within `radius` of p is Free (or Unknown when !unknown_unsafe).
bool isSafe(const OccupancyMap& map, const Vec3& p, double radius, bool unknown_unsafe);

}  // namespace ussnav
