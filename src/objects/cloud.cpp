#include "ussnav/objects/cloud.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ussnav {

namespace {

constexpr int64_t kBias = 1 << 20;  // 21-bit signed cell coordinates
constexpr uint64_t kMask = (1ULL << 21) - 1;

uint64_t packCell(int64_t x, int64_t y, int64_t z) {
  return (uint64_t(x + kBias) & kMask) | ((uint64_t(y + kBias) & kMask) << 21) |
         ((uint64_t(z + kBias) & kMask) << 42);
}

Eigen::Matrix<int64_t, 3, 1> cellOf(const Vec3f& p, double size) {
  return {int64_t(std::floor(p.x() / size)), int64_t(std::floor(p.y() / size)),
          int64_t(std::floor(p.z() / size))};
}

}  // namespace

std::vector<Vec3f> backProject(const DepthFrame& f, const std::vector<uint32_t>& mask) {
  std::vector<Vec3f> out;
  const size_t n = size_t(std::max(f.K.width, 0)) * size_t(std::max(f.K.height, 0));
  if (f.depth.size() != n || f.K.fx <= 0 || f.K.fy <= 0) return out;
  out.reserve(mask.size());
  const Mat3 R = f.T_world_camera.linear();
  const Vec3 t = f.T_world_camera.translation();
  for (uint32_t i : mask) {
    if (i >= n) continue;
    const double z = f.depth[i];
    if (!std::isfinite(z) || z <= 0 || z > f.max_range) continue;
    const int u = int(i % uint32_t(f.K.width)), v = int(i / uint32_t(f.K.width));
    const Vec3 pc((u - f.K.cx) * z / f.K.fx, (v - f.K.cy) * z / f.K.fy, z);
    out.push_back((R * pc + t).cast<float>());
  }
  return out;
}

uint64_t voxelKey(const Vec3f& p, double size) {
  const auto c = cellOf(p, size);
  return packCell(c.x(), c.y(), c.z());
}

std::vector<Vec3f> voxelDownsample(const std::vector<Vec3f>& points, double size) {
  std::unordered_map<uint64_t, uint32_t> index;
  index.reserve(points.size());
  std::vector<Vec3> sums;
  std::vector<int> counts;
  for (const auto& p : points) {
    auto [it, fresh] = index.try_emplace(voxelKey(p, size), uint32_t(sums.size()));
    if (fresh) {
      sums.push_back(p.cast<double>());
      counts.push_back(1);
    } else {
      sums[it->second] += p.cast<double>();
      ++counts[it->second];
    }
  }
  std::vector<Vec3f> out(sums.size());
  for (size_t i = 0; i < sums.size(); ++i) out[i] = (sums[i] / counts[i]).cast<float>();
  return out;
}

void PointGrid::build(const std::vector<Vec3f>& points, double radius) {
  radius_ = radius;
  cells_.clear();
  lo_ = Vec3f::Constant(std::numeric_limits<float>::infinity());
  hi_ = -lo_;
  for (const auto& p : points) {
    lo_ = lo_.cwiseMin(p);
    hi_ = hi_.cwiseMax(p);
  }
  lo_.array() -= float(radius);
  hi_.array() += float(radius);
  std::vector<std::pair<uint64_t, uint32_t>> keyed(points.size());
  for (size_t i = 0; i < points.size(); ++i) keyed[i] = {voxelKey(points[i], radius), uint32_t(i)};
  std::sort(keyed.begin(), keyed.end());
  points_.resize(points.size());
  for (size_t i = 0; i < keyed.size(); ++i) {
    points_[i] = points[keyed[i].second];
    auto [it, fresh] = cells_.try_emplace(keyed[i].first, uint32_t(i), uint32_t(i + 1));
    if (!fresh) it->second.second = uint32_t(i + 1);
  }
}

bool PointGrid::hasNeighbor(const Vec3f& p) const {
  if (points_.empty()) return false;
  // Outside the grown bounds nothing can be within the radius: no hash probes at all.
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;
  const auto c = cellOf(p, radius_);
  const float r2 = float(radius_ * radius_);
  auto probe = [&](int64_t dx, int64_t dy, int64_t dz) {
    const auto it = cells_.find(packCell(c.x() + dx, c.y() + dy, c.z() + dz));
    if (it == cells_.end()) return false;
    for (uint32_t i = it->second.first; i < it->second.second; ++i)
      if ((points_[i] - p).squaredNorm() <= r2) return true;
    return false;
  };
  if (probe(0, 0, 0)) return true;  // the point's own cell holds most hits
  for (int64_t dz = -1; dz <= 1; ++dz)
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx)
        if ((dx || dy || dz) && probe(dx, dy, dz)) return true;
  return false;
}

double geometricOverlap(const std::vector<Vec3f>& a, const PointGrid& b) {
  if (a.empty()) return 0.0;
  size_t hit = 0;
  for (const auto& p : a) hit += b.hasNeighbor(p) ? 1 : 0;
  return double(hit) / double(a.size());
}

VoxelCloud::VoxelCloud(double voxel_size, double tau)
    : voxel_(voxel_size), tau_(tau), cell_(tau + 0.5 * voxel_size),
      lo_(Vec3f::Constant(std::numeric_limits<float>::infinity())), hi_(-lo_) {}

void VoxelCloud::indexPoint(uint32_t i, const Vec3f& centre) {
  const uint64_t cell = voxelKey(centre, cell_);
  auto [it, fresh] = head_.try_emplace(cell, i);
  next_.push_back(fresh ? UINT32_MAX : it->second);
  it->second = i;
  const Vec3f half = Vec3f::Constant(float(0.5 * voxel_ + tau_));
  lo_ = lo_.cwiseMin(centre - half);
  hi_ = hi_.cwiseMax(centre + half);
}

void VoxelCloud::insert(const std::vector<Vec3f>& points) {
  for (const auto& p : points) {
    const auto c = cellOf(p, voxel_);
    auto [it, fresh] = voxel_index_.try_emplace(packCell(c.x(), c.y(), c.z()), uint32_t(sums_.size()));
    if (fresh) {
      sums_.push_back(p.cast<double>());
      counts_.push_back(1.0);
      means_.push_back(p);
      indexPoint(it->second, ((c.cast<double>().array() + 0.5) * voxel_).matrix().cast<float>());
    } else {
      const uint32_t i = it->second;
      sums_[i] += p.cast<double>();
      counts_[i] += 1.0;
      means_[i] = (sums_[i] / counts_[i]).cast<float>();
    }
  }
}

void VoxelCloud::coarsen() {
  std::vector<Vec3> sums;
  std::vector<double> counts;
  sums.swap(sums_);
  counts.swap(counts_);
  voxel_ *= 2;
  cell_ = tau_ + 0.5 * voxel_;
  voxel_index_.clear();
  means_.clear();
  head_.clear();
  next_.clear();
  lo_ = Vec3f::Constant(std::numeric_limits<float>::infinity());
  hi_ = -lo_;
  for (size_t k = 0; k < sums.size(); ++k) {
    const Vec3f mean = (sums[k] / counts[k]).cast<float>();
    const auto c = cellOf(mean, voxel_);
    auto [it, fresh] = voxel_index_.try_emplace(packCell(c.x(), c.y(), c.z()), uint32_t(sums_.size()));
    if (fresh) {
      sums_.push_back(sums[k]);
      counts_.push_back(counts[k]);
      means_.push_back(mean);
      indexPoint(it->second, ((c.cast<double>().array() + 0.5) * voxel_).matrix().cast<float>());
    } else {
      sums_[it->second] += sums[k];
      counts_[it->second] += counts[k];
      means_[it->second] = (sums_[it->second] / counts_[it->second]).cast<float>();
    }
  }
}

bool VoxelCloud::hasNeighbor(const Vec3f& p) const {
  if (means_.empty()) return false;
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;
  const auto c = cellOf(p, cell_);
  const float r2 = float(tau_ * tau_);
  auto probe = [&](int64_t dx, int64_t dy, int64_t dz) {
    const auto it = head_.find(packCell(c.x() + dx, c.y() + dy, c.z() + dz));
    if (it == head_.end()) return false;
    for (uint32_t i = it->second; i != UINT32_MAX; i = next_[i])
      if ((means_[i] - p).squaredNorm() <= r2) return true;
    return false;
  };
  if (probe(0, 0, 0)) return true;
  for (int64_t dz = -1; dz <= 1; ++dz)
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx)
        if ((dx || dy || dz) && probe(dx, dy, dz)) return true;
  return false;
}

double geometricOverlap(const std::vector<Vec3f>& a, const VoxelCloud& b, double need) {
  if (a.empty()) return 0.0;
  const double n = double(a.size());
  // Once more than (1 - need) n points missed, hits / n can no longer exceed need.
  const double max_miss = (1.0 - need) * n;
  size_t hit = 0, miss = 0;
  for (const auto& p : a) {
    if (b.hasNeighbor(p)) ++hit;
    else if (double(++miss) > max_miss) break;
  }
  return double(hit) / n;
}

double geometricOverlap(const std::vector<Vec3f>& a, const std::vector<Vec3f>& b, double tau) {
  return geometricOverlap(a, PointGrid(b, tau));
}

}  // namespace ussnav
