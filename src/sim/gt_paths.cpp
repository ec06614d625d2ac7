#include "ussnav/sim/gt_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace ussnav {

GtPlanner::GtPlanner(const GroundTruthGrid& gt, const World& world, double height, double radius)
    : res_(gt.resolution()) {
  const Aabb b = gt.window();
  x0_ = b.min.x();
  y0_ = b.min.y();
  nx_ = gt.dims().x();
  ny_ = gt.dims().y();
  double floor_z = 0.0;
  if (!world.rooms.empty()) {
    floor_z = world.rooms.front().floor_z;
  } else {
    // Scans: the floor is the lowest dense level of occupied voxels; use the 2nd percentile.
    std::vector<double> zs;
    for (const auto& c : world.obstacles.cells)
      zs.push_back(world.obstacles.origin.z() + (c.z() + 0.5) * world.obstacles.resolution);
    if (!zs.empty()) {
      std::nth_element(zs.begin(), zs.begin() + zs.size() / 50, zs.end());
      floor_z = zs[zs.size() / 50];
    }
  }
  z_ = floor_z + height;
  // Occupied columns in the band, then inflate by the radius (disc).
  std::vector<uint8_t> occ(size_t(nx_) * ny_, 0);
  const int kz0 = gt.keyOf(Vec3(0, 0, z_ - radius)).z(), kz1 = gt.keyOf(Vec3(0, 0, z_ + radius)).z();
  const Vec3i mk = gt.minKey();
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x)
      for (int z = kz0; z <= kz1; ++z)
        if (gt.label(Vec3i(mk.x() + x, mk.y() + y, z)) != GroundTruthGrid::kFree) {
          occ[idx(x, y)] = 1;
          break;
        }
  const int r = int(std::ceil(radius / res_));
  std::vector<Vec2> disc_offsets;
  std::vector<std::pair<int, int>> disc;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (std::hypot(dx, dy) * res_ <= radius + 0.5 * res_) disc.emplace_back(dx, dy);
  free_.assign(size_t(nx_) * ny_, 1);
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x) {
      if (!occ[idx(x, y)]) continue;
      for (auto [dx, dy] : disc) {
        const int u = x + dx, v = y + dy;
        if (u >= 0 && v >= 0 && u < nx_ && v < ny_) free_[idx(u, v)] = 0;
      }
    }
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x) {
      if (x == 0 || y == 0 || x == nx_ - 1 || y == ny_ - 1) free_[idx(x, y)] = 0;
      if (free_[idx(x, y)] && !world.rooms.empty() && !world.roomAt(cellCenter(x, y))) free_[idx(x, y)] = 0;
    }
}

bool GtPlanner::cellOf(const Vec2& p, int& x, int& y) const {
  x = int(std::floor((p.x() - x0_) / res_));
  y = int(std::floor((p.y() - y0_) / res_));
  return x >= 0 && y >= 0 && x < nx_ && y < ny_;
}

bool GtPlanner::freeAt(const Vec2& p) const {
  int x, y;
  return cellOf(p, x, y) && free_[idx(x, y)];
}

std::optional<Vec2> GtPlanner::nearestFree(const Vec2& p, double search) const {
  int cx, cy;
  cellOf(p, cx, cy);
  const int n = int(std::ceil(search / res_));
  std::optional<Vec2> best;
  double bd = std::numeric_limits<double>::infinity();
  for (int dy = -n; dy <= n; ++dy)
    for (int dx = -n; dx <= n; ++dx)
      if (cellFree(cx + dx, cy + dy)) {
        const Vec2 c = cellCenter(cx + dx, cy + dy);
        const double d = (c - p).norm();
        if (d < bd && d <= search) bd = d, best = c;
      }
  return best;
}

bool GtPlanner::segmentFree(const Vec2& a, const Vec2& b) const {
  const double len = (b - a).norm();
  const int n = std::max(1, int(std::ceil(len / (0.5 * res_))));
  for (int i = 0; i <= n; ++i)
    if (!freeAt(a + (b - a) * (double(i) / n))) return false;
  return true;
}

std::optional<std::vector<Vec3>> GtPlanner::shortestPath(const Vec2& from,
                                                         const std::vector<Vec2>& goals) const {
  int sx, sy;
  if (!cellOf(from, sx, sy) || !free_[idx(sx, sy)]) {
    auto nf = nearestFree(from, 0.5);
    if (!nf) return std::nullopt;
    cellOf(*nf, sx, sy);
  }
  std::vector<uint8_t> is_goal(free_.size(), 0);
  bool any = false;
  for (const auto& g : goals) {
    int gx, gy;
    if (cellOf(g, gx, gy) && free_[idx(gx, gy)]) is_goal[idx(gx, gy)] = 1, any = true;
  }
  if (!any) return std::nullopt;
  // 16-connected Dijkstra.
  static const int moves[16][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1},
                                   {2, 1}, {2, -1}, {-2, 1}, {-2, -1}, {1, 2}, {1, -2}, {-1, 2}, {-1, -2}};
  std::vector<double> dist(free_.size(), std::numeric_limits<double>::infinity());
  std::vector<int> parent(free_.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  dist[idx(sx, sy)] = 0;
  pq.emplace(0.0, idx(sx, sy));
  int reached = -1;
  while (!pq.empty()) {
    auto [d, i] = pq.top();
    pq.pop();
    if (d > dist[i]) continue;
    if (is_goal[i]) {
      reached = i;
      break;
    }
    const int x = i % nx_, y = i / nx_;
    for (const auto& m : moves) {
      const int u = x + m[0], v = y + m[1];
      if (!cellFree(u, v)) continue;
      if (std::abs(m[0]) + std::abs(m[1]) == 3) {
        // A knight move crosses the two cells between its ends.
        const int sx2 = m[0] > 0 ? 1 : -1, sy2 = m[1] > 0 ? 1 : -1;
        const bool long_x = std::abs(m[0]) == 2;
        if (!cellFree(x + sx2, y + sy2) || !cellFree(long_x ? x + sx2 : x, long_x ? y : y + sy2)) continue;
      }
      if (std::abs(m[0]) + std::abs(m[1]) == 2 && (!cellFree(u, y) || !cellFree(x, v))) continue;
      const double nd = d + std::hypot(m[0], m[1]) * res_;
      const int j = idx(u, v);
      if (nd < dist[j]) {
        dist[j] = nd;
        parent[j] = i;
        pq.emplace(nd, j);
      }
    }
  }
  if (reached < 0) return std::nullopt;
  std::vector<Vec2> cells;
  for (int i = reached; i >= 0; i = parent[i]) cells.push_back(cellCenter(i % nx_, i / nx_));
  std::reverse(cells.begin(), cells.end());
  // String pulling: from each anchor, jump to the farthest cell still in line of sight.
  std::vector<Vec3> path{Vec3(cells.front().x(), cells.front().y(), z_)};
  size_t a = 0;
  while (a + 1 < cells.size()) {
    size_t b = a + 1;
    for (size_t k = cells.size() - 1; k > a + 1; --k)
      if (segmentFree(cells[a], cells[k])) {
        b = k;
        break;
      }
    path.emplace_back(cells[b].x(), cells[b].y(), z_);
    a = b;
  }
  return path;
}

std::vector<Vec2> GtPlanner::freeSamples(int stride) const {
  std::vector<Vec2> out;
  for (int y = 0; y < ny_; y += stride)
    for (int x = 0; x < nx_; x += stride)
      if (free_[idx(x, y)]) out.push_back(cellCenter(x, y));
  return out;
}

bool GtPlanner::allRoomsConnected(const World& world) const {
  // Label connected components of free cells, then require every room to contain free cells of
  // one and the same component.
  std::vector<int> comp(free_.size(), -1);
  int ncomp = 0;
  for (size_t s = 0; s < free_.size(); ++s) {
    if (!free_[s] || comp[s] >= 0) continue;
    std::vector<int> stack{int(s)};
    comp[s] = ncomp;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      const int x = i % nx_, y = i / nx_;
      const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& m : nb)
        if (cellFree(x + m[0], y + m[1]) && comp[idx(x + m[0], y + m[1])] < 0) {
          comp[idx(x + m[0], y + m[1])] = ncomp;
          stack.push_back(idx(x + m[0], y + m[1]));
        }
    }
    ++ncomp;
  }
  int common = -1;
  for (const auto& room : world.rooms) {
    // The room's largest component.
    std::vector<int> count(ncomp, 0);
    for (int y = 0; y < ny_; ++y)
      for (int x = 0; x < nx_; ++x)
        if (free_[idx(x, y)] && pointInPolygon(cellCenter(x, y), room.polygon)) ++count[comp[idx(x, y)]];
    const auto it = std::max_element(count.begin(), count.end());
    if (it == count.end() || *it == 0) return false;
    const int c = int(it - count.begin());
    if (common < 0) common = c;
    if (c != common) return false;
  }
  return true;
}

double GtPlanner::length(const std::vector<Vec3>& p) {
  double s = 0;
  for (size_t i = 1; i < p.size(); ++i) s += (p[i] - p[i - 1]).norm();
  return s;
}

}  // namespace ussnav
