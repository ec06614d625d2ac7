#pragma once
// What the camera has seen (issue 7). With the LiDAR feeding the map, space becomes known long
// before the 87-degree depth camera looks at it, and objects are only detected in camera frames.
// CameraCoverage keeps a global 2-D map at flight height (cells of seen_resolution): a cell is
// *known* once the rolling grid holds its flight-height voxel as Free, *seen* once a camera ray
// (every seen_pixel_stride-th pixel, walked in x-y up to min(depth, seen_range)) crossed it
// at least seen_below under flight height (low enough to meet the objects standing there), or
// ended in it.
// Known-but-unseen cells form UnseenPatch targets (4-connected, cut into unseen_patch_size
// tiles, at least unseen_min_cells) with viewpoints like a frontier's: positions on three rings
// around the patch on known free cells with unseen_clearance, yaw at the patch centroid, gain =
// patch cells in the camera's field of view between seen_below / tan(vfov / 2) and seen_range
// and in 2-D line of sight through known cells. Costs: updateKnown O(window cells in one
// slice), updateSeen O(pixels / stride^2 x ray cells), patches() O(unseen cells + patches x
// candidate positions x patch cells).

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/frame.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/exploration/viewpoint.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

using Vec2i = Eigen::Vector2i;

struct UnseenPatch {
  int id = -1;                       // index in this patches() result (not stable over time)
  std::vector<Vec2i> cells;          // sorted (y, x)
  Vec3 centroid = Vec3::Zero();      // at flight height
  std::vector<Viewpoint> viewpoints; // best gain first; empty when no position sees it
};

class CameraCoverage {
 public:
  // `flight_z`: height of the map slice (the UAV's flight height), m. Throws InputError (file
  // "exploration") when a parameter is out of range.
  CameraCoverage(const ExplorationConfig& cfg, double flight_z);

  // Marks window cells whose flight-height voxel is Free as known (call after the grid update).
  void updateKnown(const RollingGrid& grid);
  // Marks the cells the camera looked at in `frame`.
  void updateSeen(const DepthFrame& frame);
  // Cells excluded from targets (e.g. a patch whose viewpoint was reached without seeing it);
  // they still count as unseen in the areas.
  void abandon(const std::vector<Vec2i>& cells);

  // Current patches of known-but-unseen cells (recomputed on each call).
  std::vector<UnseenPatch> patches() const;

  bool isKnown(const Vec2i& c) const { return flags(c) & kKnown; }
  bool isSeen(const Vec2i& c) const { return flags(c) & kSeen; }
  Vec2i cellOf(const Vec2& p) const;
  Vec3 centerOf(const Vec2i& c) const;
  double knownArea() const { return double(known_) * res_ * res_; }           // m^2
  double seenKnownArea() const { return double(seen_known_) * res_ * res_; }  // known and seen, m^2
  double resolution() const { return res_; }
  double flightZ() const { return z_; }

 private:
  static constexpr uint8_t kKnown = 1, kSeen = 2, kAbandoned = 4;
  static uint64_t pack(const Vec2i& c) { return uint64_t(uint32_t(c.x())) << 32 | uint32_t(c.y()); }
  static Vec2i unpack(uint64_t k) { return Vec2i(int32_t(uint32_t(k >> 32)), int32_t(uint32_t(k))); }
  uint8_t flags(const Vec2i& c) const;
  void set(const Vec2i& c, uint8_t f);
  bool losKnown(const Vec2i& a, const Vec2i& b) const;
  bool clear(const Vec2i& c, int radius_cells) const;

  ExplorationConfig cfg_;
  double res_, z_;
  std::unordered_map<uint64_t, uint8_t> cells_;
  size_t known_ = 0, seen_known_ = 0;
};

}  // namespace ussnav
