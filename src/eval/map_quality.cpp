#include "ussnav/eval/map_quality.hpp"

#include <algorithm>
#include <cmath>

#include "ussnav/core/random.hpp"
#include "ussnav/skeleton/graph_search.hpp"

namespace ussnav {

namespace {
int64_t pack(const Vec3i& k) {
  return (int64_t(k.x() + (1 << 20)) << 42) | (int64_t(k.y() + (1 << 20)) << 21) | int64_t(k.z() + (1 << 20));
}
Vec3i unpack(int64_t v) {
  const int64_t m = (1 << 21) - 1;
  return Vec3i(int((v >> 42) & m) - (1 << 20), int((v >> 21) & m) - (1 << 20), int(v & m) - (1 << 20));
}
}  // namespace

ObservedFreeSpace::ObservedFreeSpace(double resolution, double z_min, double z_max)
    : res_(resolution), kz0_(int(std::floor(z_min / resolution))), kz1_(int(std::floor(z_max / resolution))) {}

void ObservedFreeSpace::update(const RollingGrid& grid) {
  for (const auto& c : grid.changes()) {
    if (c.key.z() < kz0_ || c.key.z() > kz1_) continue;
    // Leaving the window (reset to Unknown) keeps the last observation.
    if (c.after == VoxelState::Free)
      free_[pack(c.key)] = 1;
    else if (c.after == VoxelState::Occupied)
      free_[pack(c.key)] = 0;
  }
}

std::vector<Vec3> ObservedFreeSpace::freeCenters() const {
  std::vector<std::pair<int64_t, Vec3>> keyed;
  for (const auto& [k, f] : free_)
    if (f) keyed.emplace_back(k, (unpack(k).cast<double>() + Vec3::Constant(0.5)) * res_);
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec3> out;
  out.reserve(keyed.size());
  for (auto& kv : keyed) out.push_back(kv.second);
  return out;
}

bool polylineCollisionFree(const GroundTruthGrid& gt, const std::vector<Vec3>& pts) {
  for (size_t i = 1; i < pts.size(); ++i) {
    const Vec3 d = pts[i] - pts[i - 1];
    const double len = d.norm();
    if (len < 1e-9) continue;
    if (gt.occupiedAt(pts[i - 1]) || gt.raycast(pts[i - 1], d / len, len).hit) return false;
  }
  return pts.empty() || !gt.occupiedAt(pts.back());
}

SkeletonQuality skeletonQuality(const ConnectivityGraph& graph, const RollingGrid& grid,
                                const GroundTruthGrid& gt, const GtPlanner& planner,
                                const ObservedFreeSpace& observed, double radius, int pairs, uint64_t seed) {
  SkeletonQuality q;
  const std::vector<Vec3> free = observed.freeCenters();
  q.observed_free_voxels = int(free.size());
  if (free.empty()) return q;
  size_t covered = 0, safe_covered = 0;
  std::vector<Vec3> safe;
  for (const auto& p : free) {
    const bool in = graph.containingNode(p) >= 0;
    covered += in;
    if (gt.sphereCollides(p, radius)) continue;
    safe.push_back(p);
    safe_covered += in;
  }
  q.free_space_coverage = double(covered) / double(free.size());
  q.navigable_voxels = int(safe.size());
  q.navigable_coverage = safe.empty() ? 0.0 : double(safe_covered) / double(safe.size());
  if (safe.size() < 2) return q;
  Rng rng(seed);
  int ok = 0, tried = 0;
  double ratio_sum = 0;
  for (int attempt = 0; tried < pairs && attempt < pairs * 20; ++attempt) {
    const Vec3 a = safe[size_t(rng.uniformInt(0, int(safe.size()) - 1))];
    const Vec3 b = safe[size_t(rng.uniformInt(0, int(safe.size()) - 1))];
    if ((a - b).norm() < 1.0) continue;
    const auto gt_path = planner.shortestPath(a.head<2>(), b.head<2>());
    if (!gt_path) continue;  // not reachable for the UAV: not a fair pair
    ++tried;
    const GraphPath p = findGraphPath(graph, grid, a, b);
    q.not_found += !p.found;
    if (p.found && !polylineCollisionFree(gt, p.points)) ++q.colliding;
    if (p.found && polylineCollisionFree(gt, p.points)) {
      ++ok;
      ratio_sum += p.length / std::max(1e-6, GtPlanner::length(*gt_path));
    }
  }
  q.pairs = tried;
  q.path_success = tried ? double(ok) / tried : 0.0;
  q.mean_path_ratio = ok ? ratio_sum / ok : 0.0;
  return q;
}

}  // namespace ussnav
