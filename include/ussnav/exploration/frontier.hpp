#pragma once
// Frontiers of the paper (Sec. V-A, GCM-aided frontier extraction, after FUEL): free voxels in
// a height band with an Unknown 6-neighbour (outside the window counts as Unknown, as in
// RollingGrid::state), not in a visited Coverage Mask cell. Judged incrementally, only where
// the grid's change log says a frame changed something (box + 1 voxel) and where voxels enter
// the window: O(those voxels + frontier cells re-clustered); a whole-window rescan only when
// change entries were missed. Hence exact for every known voxel not on the window's outer
// layer; on that layer only voxels a frame touched are frontiers (free space the sensor saw
// run out of the window), so the trailing edge of a moving window makes none. With
// remember_known_band a neighbour outside the window counts as Unknown only if that voxel was
// never known while in the window (BandMemory): looking back at space flown before,
// the window's edge makes no frontier (cells cut by a wall are never visited, so the Coverage
// Mask alone would let those flicker: there while away, gone when approached). With
// open_in_visited as well, a voxel in a visited cell is still a frontier where an x-y
// neighbour was never known (a room seen through a door leaves its cells mostly known).
// Connected cells (26-neighbours) of at least min_cluster_cells form clusters, split by PCA
// while longer than max_cluster_extent; each has viewpoints (viewpoint.hpp, computed when the
// cluster is made) and the connectivity-graph node given when it was made. Cells that leave
// the window persist untouched until a frame makes them known or a visited coverage cell
// covers them (with open_in_visited, until they re-enter the window: there is no judging them
// outside it). Memory: one hash entry per frontier cell, one bit per band voxel ever
// known (64 bits per x-y column).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/exploration/viewpoint.hpp"
#include "ussnav/mapping/coverage_mask.hpp"
#include "ussnav/mapping/band_memory.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

struct Frontier {
  int id = -1;                       // stable while the frontier's cells do not change
  std::vector<Vec3i> cells;          // voxel keys, sorted (z, y, x)
  Vec3 centroid = Vec3::Zero();      // mean of the cell centres
  Aabb box;                          // bounds of the cells' voxels
  std::vector<Viewpoint> viewpoints; // by gain, best first; may be empty
  int anchor_node = -1;              // connectivity-graph node of the UAV when made
  double created_time = 0.0;
};

struct FrontierUpdate {
  std::vector<int> added;    // ids of frontiers made this update
  std::vector<int> removed;  // ids that no longer exist
  int cells_added = 0;       // frontier cells that appeared
  int cells_removed = 0;     // frontier cells that went (known, not frontier, or visited)
  int voxels_scanned = 0;    // voxels re-judged
  bool full_rescan = false;  // change entries were missed (or first update): whole window
};

class FrontierFinder {
 public:
  // Throws InputError (file "exploration") on an empty height band or r_min > r_max.
  explicit FrontierFinder(const ExplorationConfig& cfg);

  // Consumes grid.changes() appended since the previous update (call after insertion and
  // CoverageMask::update, before clearChanges). New frontiers get anchor_node and `time`.
  FrontierUpdate update(const RollingGrid& grid, const CoverageMask& gcm, int anchor_node, double time);

  // Current frontiers, sorted by id.
  const std::vector<Frontier>& frontiers() const { return frontiers_; }
  const Frontier* find(int id) const;
  // Every frontier cell, also those in clusters under min_cluster_cells (not frontiers yet).
  std::vector<Vec3i> frontierCells() const;
  bool isFrontierCell(const Vec3i& key) const { return cells_.count(pack(key)) != 0; }
  size_t cellCount() const { return cells_.size(); }

  // The rule applied to an in-window voxel (for tests and tools); `seen` (may be null): band
  // voxels known before, which make an out-of-window neighbour no Unknown.
  static bool isFrontierVoxel(const RollingGrid& grid, const CoverageMask& gcm, const Vec3i& key,
                              const ExplorationConfig& cfg, const BandMemory* seen = nullptr);

  const ExplorationConfig& config() const { return cfg_; }

  static uint64_t pack(const Vec3i& k) {
    return uint64_t(uint32_t(k.x()) & 0x1FFFFF) << 42 | uint64_t(uint32_t(k.y()) & 0x1FFFFF) << 21 |
           uint64_t(uint32_t(k.z()) & 0x1FFFFF);
  }
  static Vec3i unpack(uint64_t p) {
    auto s = [](uint64_t v) { return int(int32_t(uint32_t(v << 11)) >> 11); };  // sign-extend 21 bits
    return Vec3i(s(p >> 42 & 0x1FFFFF), s(p >> 21 & 0x1FFFFF), s(p & 0x1FFFFF));
  }

 private:
  void scanBox(const RollingGrid& grid, const CoverageMask& gcm, Vec3i lo, Vec3i hi, FrontierUpdate& up);
  void dropVisited(const RollingGrid& grid, const CoverageMask& gcm, FrontierUpdate& up);
  void recluster(const RollingGrid& grid, int anchor_node, double time, FrontierUpdate& up);
  void splitCluster(std::vector<Vec3i>& cells, double res, std::vector<std::vector<Vec3i>>& out) const;
  void markAffected(int owner);

  ExplorationConfig cfg_;
  BandMemory seen_;                          // band voxels ever known (remember_known_band)
  std::unordered_map<uint64_t, int> cells_;  // frontier cell -> frontier id, -1 unclustered
  std::vector<Frontier> frontiers_;
  std::unordered_map<int, size_t> index_;    // id -> position in frontiers_
  std::vector<uint64_t> touched_;            // cells added or unclustered-and-reached this update
  std::vector<int> affected_;                // frontier ids that lost cells or gained neighbours
  int next_id_ = 0;
  uint64_t consumed_ = 0;
  bool initialised_ = false;
  Vec3i last_min_key_ = Vec3i::Zero();
  size_t last_visited_count_ = 0;
};

}  // namespace ussnav
