#pragma once
// An OccupancyMap adaptor that inflates obstacles by a radius, so that the path searches and
// line-of-sight checks written for voxels (castRay, findGraphPath, shortcutPolyline) keep a
// UAV's body clear of walls: a voxel is Occupied when an Occupied voxel of the base map lies
// within `radius` of its centre, else Unknown when the base says Unknown, else Free. (An unseen
// voxel next to a seen wall is Occupied too: a path through unseen space, the last resort, still
// keeps its margin from what is known.) Answers are
// cached per voxel for the adaptor's lifetime: make one per planning step (the base map must
// not change meanwhile). Cost: O((radius / res)^3) base lookups per new voxel.

#include <cstdint>
#include <unordered_map>

#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

class InflatedMap final : public OccupancyMap {
 public:
  // Voxels whose centre lies outside [z_min, z_max] count as Occupied (a flight band).
  InflatedMap(const RollingGrid& base, double radius, double z_min = -1e30, double z_max = 1e30)
      : base_(base), radius_(radius), z_min_(z_min), z_max_(z_max) {}
  double resolution() const override { return base_.resolution(); }
  VoxelState state(const Vec3i& key) const override;
  bool inWindow(const Vec3i& key) const override { return base_.inWindow(key); }
  Aabb window() const override { return base_.window(); }
  double radius() const { return radius_; }

 private:
  const RollingGrid& base_;
  double radius_, z_min_, z_max_;
  mutable std::unordered_map<uint64_t, VoxelState> cache_;
};

}  // namespace ussnav
