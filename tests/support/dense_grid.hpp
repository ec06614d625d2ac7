#pragma once
// A dense hand-made occupancy grid for the skeleton tests and benchmark: an OccupancyMap over a
// fixed box, with helpers that carve free boxes, put walls, mark unknown regions, and a movable
// "window" that hides everything outside it (to emulate the rolling grid). Header-only so the
// benchmarks use it without the test library; scenes built from it are in skeleton_scenes.hpp.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ussnav/mapping/occupancy.hpp"

namespace ussnav::test {

class DenseGrid : public OccupancyMap {
 public:
  // Voxels covering `bounds` (rounded outwards to the voxel lattice), all set to `fill`.
  DenseGrid(const Aabb& bounds, double resolution, VoxelState fill = VoxelState::Unknown) : res_(resolution) {
    for (int i = 0; i < 3; ++i) {
      lo_[i] = int(std::floor(bounds.min[i] / res_ + 1e-9));
      dims_[i] = std::max(1, int(std::ceil(bounds.max[i] / res_ - 1e-9)) - lo_[i]);
    }
    bounds_.min = lo_.cast<double>() * res_;
    bounds_.max = (lo_ + dims_).cast<double>() * res_;
    cells_.assign(size_t(dims_.x()) * dims_.y() * dims_.z(), uint8_t(fill));
    resetWindow();
  }

  double resolution() const override { return res_; }
  VoxelState state(const Vec3i& key) const override {
    return inWindow(key) ? VoxelState(cells_[index(key)]) : VoxelState::Unknown;
  }
  bool inWindow(const Vec3i& key) const override {
    return (key.array() >= win_lo_.array()).all() && (key.array() <= win_hi_.array()).all();
  }
  Aabb window() const override {
    Aabb w;
    w.min = win_lo_.cast<double>() * res_;
    w.max = (win_hi_ + Vec3i::Ones()).cast<double>() * res_;
    return w;
  }

  // Sets every voxel whose centre lies in `box`.
  void fill(const Aabb& box, VoxelState s) {
    Vec3i a, b;
    for (int i = 0; i < 3; ++i) {
      a[i] = std::max(lo_[i], int(std::ceil(box.min[i] / res_ - 0.5 - 1e-9)));
      b[i] = std::min(lo_[i] + dims_[i] - 1, int(std::floor(box.max[i] / res_ - 0.5 + 1e-9)));
    }
    for (int z = a.z(); z <= b.z(); ++z)
      for (int y = a.y(); y <= b.y(); ++y)
        for (int x = a.x(); x <= b.x(); ++x) cells_[index(Vec3i(x, y, z))] = uint8_t(s);
  }
  void carve(const Aabb& box) { fill(box, VoxelState::Free); }
  void wall(const Aabb& box) { fill(box, VoxelState::Occupied); }
  void hide(const Aabb& box) { fill(box, VoxelState::Unknown); }
  void set(const Vec3i& key, VoxelState s) {
    if (inGrid(key)) cells_[index(key)] = uint8_t(s);
  }
  // The state stored for `key`, ignoring the window (Unknown outside the grid).
  VoxelState stored(const Vec3i& key) const {
    return inGrid(key) ? VoxelState(cells_[index(key)]) : VoxelState::Unknown;
  }
  // Restricts the map to `w` (state Unknown, inWindow false outside); resetWindow() undoes it.
  void setWindow(const Aabb& w) {
    for (int i = 0; i < 3; ++i) {
      win_lo_[i] = std::max(lo_[i], int(std::floor(w.min[i] / res_ + 1e-9)));
      win_hi_[i] = std::min(lo_[i] + dims_[i] - 1, int(std::ceil(w.max[i] / res_ - 1e-9)) - 1);
    }
  }
  void resetWindow() {
    win_lo_ = lo_;
    win_hi_ = lo_ + dims_ - Vec3i::Ones();
  }
  // Voxel count in a state (inside the window only).
  size_t count(VoxelState s) const {
    size_t n = 0;
    for (int z = win_lo_.z(); z <= win_hi_.z(); ++z)
      for (int y = win_lo_.y(); y <= win_hi_.y(); ++y)
        for (int x = win_lo_.x(); x <= win_hi_.x(); ++x) n += cells_[index(Vec3i(x, y, z))] == uint8_t(s);
    return n;
  }
  const Aabb& bounds() const { return bounds_; }
  // Keys of the window, for loops over all voxels (inclusive).
  Vec3i minKey() const { return win_lo_; }
  Vec3i maxKey() const { return win_hi_; }

 private:
  bool inGrid(const Vec3i& k) const {
    return (k.array() >= lo_.array()).all() && (k.array() < (lo_ + dims_).array()).all();
  }
  size_t index(const Vec3i& k) const {
    const Vec3i r = k - lo_;
    return (size_t(r.z()) * dims_.y() + r.y()) * dims_.x() + r.x();
  }
  double res_;
  Aabb bounds_;
  Vec3i lo_, dims_;
  Vec3i win_lo_, win_hi_;
  std::vector<uint8_t> cells_;
};

}  // namespace ussnav::test
