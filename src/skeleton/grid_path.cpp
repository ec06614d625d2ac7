#include "ussnav/skeleton/grid_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace ussnav {

double polylineLength(const std::vector<Vec3>& pts) {
  double len = 0.0;
  for (size_t i = 1; i < pts.size(); ++i) len += (pts[i] - pts[i - 1]).norm();
  return len;
}

bool polylineClear(const OccupancyMap& map, const std::vector<Vec3>& pts, bool unknown_blocks) {
  for (size_t i = 1; i < pts.size(); ++i)
    if (!lineOfSight(map, pts[i - 1], pts[i], unknown_blocks)) return false;
  return true;
}

std::vector<Vec3> shortcutPolyline(const OccupancyMap& map, const std::vector<Vec3>& pts,
                                   bool unknown_blocks) {
  if (pts.size() <= 2) return pts;
  std::vector<Vec3> out{pts.front()};
  size_t i = 0;
  while (i + 1 < pts.size()) {
    size_t next = i + 1;
    for (size_t j = pts.size() - 1; j > i + 1; --j)
      if (lineOfSight(map, pts[i], pts[j], unknown_blocks)) {
        next = j;
        break;
      }
    out.push_back(pts[next]);
    i = next;
  }
  return out;
}

std::optional<std::vector<Vec3>> gridPath(const OccupancyMap& map, const Vec3& a, const Vec3& b,
                                          double max_length, bool unknown_blocks) {
  const double res = map.resolution();
  const Vec3i ka = map.keyOf(a), kb = map.keyOf(b);
  const double direct = (b - a).norm();
  if (direct > max_length) return std::nullopt;
  if (ka == kb) return std::vector<Vec3>{a, b};
  // Every voxel on a path of length <= L lies within (L - |ab|)/2 of the segment's box.
  const double slack = 0.5 * (max_length - direct) + res;
  Vec3i lo, hi;
  for (int i = 0; i < 3; ++i) {
    lo[i] = int(std::floor((std::min(a[i], b[i]) - slack) / res));
    hi[i] = int(std::floor((std::max(a[i], b[i]) + slack) / res));
  }
  const Vec3i dims = hi - lo + Vec3i::Ones();
  const size_t n = size_t(dims.x()) * dims.y() * dims.z();
  if (n > 4'000'000) return std::nullopt;  // guard against absurd max_length
  auto idx = [&](const Vec3i& k) {
    const Vec3i r = k - lo;
    return (size_t(r.z()) * dims.y() + r.y()) * dims.x() + r.x();
  };
  auto inside = [&](const Vec3i& k) {
    return (k.array() >= lo.array()).all() && (k.array() <= hi.array()).all();
  };
  auto passable = [&](const Vec3i& k) {
    if (k == kb) return true;
    const VoxelState s = map.state(k);
    return s == VoxelState::Free || (!unknown_blocks && s == VoxelState::Unknown);
  };
  const Vec3 goal_c = map.centerOf(kb);
  auto h = [&](const Vec3i& k) { return (map.centerOf(k) - goal_c).norm(); };

  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> g(n, kInf);
  std::vector<int> parent(n, -1);
  std::vector<char> closed(n, 0);
  using Item = std::pair<float, size_t>;  // f, index; ties broken by index: deterministic
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  // Path length is measured between voxel centres plus the two end stubs.
  const double stub = (a - map.centerOf(ka)).norm() + (b - goal_c).norm();
  const double budget = max_length - stub;
  g[idx(ka)] = 0.f;
  open.push({float(h(ka)), idx(ka)});
  auto keyOfIndex = [&](size_t i) {
    const int x = int(i % size_t(dims.x()));
    const int y = int((i / size_t(dims.x())) % size_t(dims.y()));
    const int z = int(i / (size_t(dims.x()) * dims.y()));
    return Vec3i(lo.x() + x, lo.y() + y, lo.z() + z);
  };
  bool found = false;
  while (!open.empty()) {
    const auto [f, i] = open.top();
    open.pop();
    if (closed[i]) continue;
    if (f > budget + 1e-6) break;
    closed[i] = 1;
    const Vec3i k = keyOfIndex(i);
    if (k == kb) {
      found = true;
      break;
    }
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!dx && !dy && !dz) continue;
          const Vec3i nk = k + Vec3i(dx, dy, dz);
          if (!inside(nk) || !passable(nk)) continue;
          // Diagonal moves may not cut a blocked voxel corner: the axis neighbours must pass.
          if ((dx && dy && (!passable(k + Vec3i(dx, 0, 0)) || !passable(k + Vec3i(0, dy, 0)))) ||
              (dx && dz && (!passable(k + Vec3i(dx, 0, 0)) || !passable(k + Vec3i(0, 0, dz)))) ||
              (dy && dz && (!passable(k + Vec3i(0, dy, 0)) || !passable(k + Vec3i(0, 0, dz)))))
            continue;
          const size_t ni = idx(nk);
          if (closed[ni]) continue;
          const float ng = g[i] + float(res * std::sqrt(double(dx * dx + dy * dy + dz * dz)));
          if (ng < g[ni]) {
            g[ni] = ng;
            parent[ni] = int(i);
            const double nf = ng + h(nk);
            if (nf <= budget + 1e-6) open.push({float(nf), ni});
          }
        }
  }
  if (!found) return std::nullopt;
  std::vector<Vec3> pts{b};
  for (int i = parent[idx(kb)]; i >= 0; i = parent[size_t(i)]) {
    const Vec3i k = keyOfIndex(size_t(i));
    pts.push_back(k == ka ? a : map.centerOf(k));
  }
  if (pts.back() != a) pts.push_back(a);
  std::reverse(pts.begin(), pts.end());
  std::vector<Vec3> out = shortcutPolyline(map, pts, unknown_blocks);
  if (polylineLength(out) > max_length + 1e-9 || !polylineClear(map, out, unknown_blocks))
    return std::nullopt;
  return out;
}

}  // namespace ussnav
