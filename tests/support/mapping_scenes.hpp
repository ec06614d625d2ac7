#pragma once
// Analytic scenes for the mapping tests and benchmark: a union of solid axis-aligned boxes
// (walls, floor, ceiling, furniture) with exact ray casting, a pinhole depth renderer and a
// LiDAR-like scan of the same geometry, and the ground-truth oracles the tests judge by.
// No simulator involved: every depth value is a closed-form ray-box intersection.

#include <cstdint>
#include <vector>

#include "ussnav/core/frame.hpp"
#include "ussnav/core/types.hpp"

namespace ussnav::test {

struct BoxScene {
  std::vector<Aabb> solids;

  // Distance along unit `dir` from `o` to the first solid surface; +inf if none within max.
  double raycast(const Vec3& o, const Vec3& dir, double max_dist) const;
  bool insideSolid(const Vec3& p) const;
  // The voxel's box meets no solid with positive volume (touching a face is still free).
  bool voxelFreeInTruth(const Vec3i& key, double res) const;
  // The voxel's box grown by `margin` on every side meets a solid and also holds free space,
  // i.e. a true surface passes within `margin` of the voxel.
  bool voxelNearSurface(const Vec3i& key, double res, double margin) const;
};

// A closed room: interior [lo, hi], walls/floor/ceiling `wall` thick, plus (if `furnished`)
// a table-like box, a cabinet against a wall and a pillar. Faces are deliberately off the
// 0.1 m voxel lattice.
BoxScene boxRoom(const Vec3& lo, const Vec3& hi, double wall = 0.2, bool furnished = true);
// A straight corridor along +x from x = 0 to `length`, `width` wide (centred on y = 0),
// floor at z = 0, ceiling at `height`, with a box every 10 m alternating sides.
BoxScene corridor(double length, double width, double height);

// Camera-to-world of an optical-frame camera at `position`, body yaw `yaw`, pitched down by
// `pitch` (radians).
Iso3 cameraPose(const Vec3& position, double yaw, double pitch = 0.0);

// z-depth image by exact ray casting; 0 where nothing lies within max_range (z-depth).
// Gaussian noise (std, metres) on the depth when noise_std > 0.
DepthFrame renderDepth(const BoxScene& scene, const Intrinsics& K, const Iso3& T_world_camera,
                       double max_range, double noise_std = 0.0, uint64_t seed = 1);

// `n` rays spread over 360 degrees of azimuth and [vmin, vmax] degrees of elevation (a
// golden-angle pattern, like a non-repetitive Mid-360 scan), rotated by `phase` radians.
// Hits become points (with range noise), misses no_return_dirs.
PointCloudScan renderScan(const BoxScene& scene, const Vec3& origin, int n, double vmin_deg,
                          double vmax_deg, double max_range, double phase = 0.0,
                          double noise_std = 0.0, uint64_t seed = 1);

}  // namespace ussnav::test
