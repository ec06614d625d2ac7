#include "ussnav/objects/cloud.hpp"

#include <algorithm>
#include <cmath>

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
  const auto c = cellOf(p, radius_);
  const float r2 = float(radius_ * radius_);
  for (int64_t dz = -1; dz <= 1; ++dz)
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(packCell(c.x() + dx, c.y() + dy, c.z() + dz));
        if (it == cells_.end()) continue;
        for (uint32_t i = it->second.first; i < it->second.second; ++i)
          if ((points_[i] - p).squaredNorm() <= r2) return true;
      }
  return false;
}

double geometricOverlap(const std::vector<Vec3f>& a, const PointGrid& b) {
  if (a.empty()) return 0.0;
  size_t hit = 0;
  for (const auto& p : a) hit += b.hasNeighbor(p) ? 1 : 0;
  return double(hit) / double(a.size());
}

double geometricOverlap(const std::vector<Vec3f>& a, const std::vector<Vec3f>& b, double tau) {
  return geometricOverlap(a, PointGrid(b, tau));
}

}  // namespace ussnav
