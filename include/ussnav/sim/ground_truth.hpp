#pragma once
// Ground-truth occupancy of a World as a dense voxel grid (default 0.05 m): walls with their
// openings cut, floor and ceiling slabs, objects labelled with their instance id, scanned
// obstacle voxels. Used by the simulated sensors (exact, fast DDA ray casting) and by the
// evaluation (shortest paths, success checks) — never by the navigation pipeline.
// Memory: 2 bytes per voxel (a 30 x 20 x 3 m floor at 0.05 m is about 58 MB).

#include <cstdint>
#include <vector>

#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

class GroundTruthGrid : public OccupancyMap {
 public:
  static constexpr uint16_t kFree = 0;
  static constexpr uint16_t kStructure = 0xFFFF;

  // Rasterises `world` at `resolution`, with `margin` metres of free space around its bounds.
  GroundTruthGrid(const World& world, double resolution = 0.05, double margin = 0.3);

  // OccupancyMap: Occupied for any labelled voxel, Free otherwise, Unknown outside the grid.
  double resolution() const override { return res_; }
  VoxelState state(const Vec3i& key) const override;
  bool inWindow(const Vec3i& key) const override;
  Aabb window() const override { return bounds_; }

  // Raw label: kFree, kStructure, or object index + 1 (see instanceOfLabel).
  uint16_t label(const Vec3i& key) const;
  uint16_t labelAt(const Vec3& p) const { return label(keyOf(p)); }
  bool occupiedAt(const Vec3& p) const { return labelAt(p) != kFree; }
  // Object instance id for a label (0 for free/structure).
  int instanceOfLabel(uint16_t label) const;

  struct Hit {
    bool hit = false;
    double range = 0.0;       // metres along the ray to the first occupied voxel
    uint16_t label = kFree;
  };
  // First occupied voxel along origin + t * dir (dir unit), t <= max_range. The voxel holding
  // the origin is skipped when the origin is inside an obstacle.
  Hit raycast(const Vec3& origin, const Vec3& dir, double max_range) const;

  // True when a sphere of `radius` at p touches an occupied voxel (or leaves the grid).
  bool sphereCollides(const Vec3& p, double radius) const;

  const Vec3i& dims() const { return dims_; }
  const Vec3i& minKey() const { return min_key_; }
  size_t bytes() const { return labels_.size() * sizeof(uint16_t); }
  size_t occupiedCount() const;

 private:
  size_t index(const Vec3i& key) const {
    const Vec3i l = key - min_key_;
    return (size_t(l.z()) * dims_.y() + l.y()) * dims_.x() + l.x();
  }
  void rasterizeWall(const Wall& w);
  void carveOpenings(const Wall& w);
  void rasterizeBox(const OrientedBox& b, uint16_t label);
  void fillKeyBox(const Vec3& lo, const Vec3& hi, uint16_t label);

  void buildBlocks();
  // Voxel DDA from o along dir, starting at parameter t0 (t0 > 0: the voxel there is tested
  // too), confined to block `bkey` (kBlock^3 voxels). Returns true on a hit (filled into h).
  bool walkBlock(const Vec3& o, const Vec3& dir, double t0, double max_range, const Vec3i& bkey, Hit& h) const;

  static constexpr int kBlock = 8;  // empty-space skipping: blocks of 8^3 voxels
  double res_;
  Vec3i min_key_, dims_;
  Vec3i bdims_;
  std::vector<uint8_t> block_occupied_;
  Aabb bounds_;
  std::vector<uint16_t> labels_;
  std::vector<int> instance_of_label_;  // label -> object id
};

}  // namespace ussnav
