#pragma once
// MappedObject point clouds (paper Sec. IV-C step 2 and Eq. 1): back-projection of a mask's depth
// pixels to the world frame, voxel downsampling, and the geometric similarity Omega(Ci, Cj) =
// the fraction of Ci's points with a point of Cj within tau. Omega uses a hash grid of cell tau
// over Cj, so one query probes 27 cells: O(|Ci|) after an O(|Cj|) build.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ussnav/core/frame.hpp"
#include "ussnav/core/types.hpp"

namespace ussnav {

// World-frame points of the mask's pixels with a valid depth (finite, > 0, <= frame.max_range):
// p_cam = ((u - cx) z / fx, (v - cy) z / fy, z), p_world = T_world_camera p_cam. Indices outside
// the image are ignored.
std::vector<Vec3f> backProject(const DepthFrame& frame, const std::vector<uint32_t>& mask);

// Key of the voxel of edge `size` holding p (floor division; 21 bits per axis, so +-1e6 cells).
uint64_t voxelKey(const Vec3f& p, double size);

// One point per occupied voxel of edge `size`: the mean of the points in it, in the order the
// voxels were first hit.
std::vector<Vec3f> voxelDownsample(const std::vector<Vec3f>& points, double size);

// Fixed-radius neighbour test over a point set (a hash grid of cell = radius).
class PointGrid {
 public:
  PointGrid() = default;
  PointGrid(const std::vector<Vec3f>& points, double radius) { build(points, radius); }
  void build(const std::vector<Vec3f>& points, double radius);
  // True when some point lies within radius() of p (distance <= radius).
  bool hasNeighbor(const Vec3f& p) const;
  double radius() const { return radius_; }
  size_t size() const { return points_.size(); }

 private:
  double radius_ = 0.1;
  Vec3f lo_ = Vec3f::Zero(), hi_ = Vec3f::Zero();  // bounds grown by the radius
  std::vector<Vec3f> points_;  // grouped by cell
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> cells_;  // key -> [begin, end)
};

// A voxel-downsampled cloud that grows by insertion (an object's cloud): one point per voxel,
// the mean of everything that fell in it, plus a neighbour index for Omega queries within tau.
// The index files each voxel under its *centre* in a hash grid of cell tau + voxel/2: a mean
// never leaves its voxel, so the 27 cells around a query hold every point within tau and the
// index never needs rebuilding when means move. insert() is O(|points|); coarsen() O(size).
class VoxelCloud {
 public:
  VoxelCloud(double voxel_size, double tau);
  // Adds points: new voxels get them, occupied voxels update their mean.
  void insert(const std::vector<Vec3f>& points);
  // Doubles the voxel size, pooling the sums of voxels that fall together.
  void coarsen();
  const std::vector<Vec3f>& points() const { return means_; }
  size_t size() const { return means_.size(); }
  double voxelSize() const { return voxel_; }
  double tau() const { return tau_; }
  // True when some point lies within tau of p.
  bool hasNeighbor(const Vec3f& p) const;

 private:
  void indexPoint(uint32_t i, const Vec3f& voxel_centre);

  double voxel_, tau_, cell_;
  std::unordered_map<uint64_t, uint32_t> voxel_index_;  // voxel key -> point index
  std::vector<Vec3> sums_;
  std::vector<double> counts_;
  std::vector<Vec3f> means_;
  std::unordered_map<uint64_t, uint32_t> head_;  // cell key -> first point index in it
  std::vector<uint32_t> next_;                   // next point index in the same cell
  Vec3f lo_, hi_;                                // voxel extents grown by tau
};

// Omega(a, b) of paper Eq. 1 with tau = b.radius(): fraction of a's points within tau of b.
// 0 when a is empty.
double geometricOverlap(const std::vector<Vec3f>& a, const PointGrid& b);
// The same against a VoxelCloud (tau = b.tau()). With `need` > 0 the count stops as soon as
// the result cannot exceed `need`: the value is exact when it is above `need`, and some value
// <= need otherwise (association only asks "is it above the threshold, and by how much").
double geometricOverlap(const std::vector<Vec3f>& a, const VoxelCloud& b, double need = 0.0);
// Convenience: builds the grid of b.
double geometricOverlap(const std::vector<Vec3f>& a, const std::vector<Vec3f>& b, double tau);

}  // namespace ussnav
