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

bool tubeOfSight(const OccupancyMap& map, const Vec3& a, const Vec3& b, double clearance,
                 bool unknown_blocks) {
  if (!lineOfSight(map, a, b, unknown_blocks)) return false;
  const Vec3 d = b - a;
  if (clearance <= 0.0 || d.norm() < 1e-9) return true;
  const Vec3 dir = d.normalized();
  // Any unit vector not parallel to dir gives the two sideways directions.
  const Vec3 other = std::abs(dir.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 u = dir.cross(other).normalized() * clearance;
  const Vec3 v = dir.cross(u).normalized() * clearance;
  for (const Vec3& o : {u, Vec3(-u), v, Vec3(-v)})
    if (!lineOfSight(map, a + o, b + o, unknown_blocks)) return false;
  return true;
}

bool polylineClear(const OccupancyMap& map, const std::vector<Vec3>& pts, bool unknown_blocks,
                   double clearance) {
  for (size_t i = 1; i < pts.size(); ++i)
    if (!tubeOfSight(map, pts[i - 1], pts[i], clearance, unknown_blocks)) return false;
  return true;
}

bool polylinePassesNear(const std::vector<Vec3>& pts, std::span<const Vec3> spots, double radius) {
  for (const Vec3& s : spots) {
    if (pts.size() == 1 && (s - pts[0]).norm() <= radius) return true;
    for (size_t i = 1; i < pts.size(); ++i) {
      const Vec3 &a = pts[i - 1], d = pts[i] - a;
      const double l2 = d.squaredNorm();
      const double t = l2 > 0.0 ? std::clamp((s - a).dot(d) / l2, 0.0, 1.0) : 0.0;
      if ((a + t * d - s).norm() <= radius) return true;
    }
  }
  return false;
}

std::vector<Vec3> shortcutPolyline(const OccupancyMap& map, const std::vector<Vec3>& pts,
                                   bool unknown_blocks, double clearance) {
  if (pts.size() <= 2) return pts;
  std::vector<Vec3> out{pts.front()};
  size_t i = 0;
  while (i + 1 < pts.size()) {
    size_t next = i + 1;
    for (size_t j = pts.size() - 1; j > i + 1; --j)
      if (tubeOfSight(map, pts[i], pts[j], clearance, unknown_blocks)) {
        next = j;
        break;
      }
    out.push_back(pts[next]);
    i = next;
  }
  return out;
}

std::optional<std::vector<Vec3>> gridPath(const OccupancyMap& map, const Vec3& a, const Vec3& b,
                                          double max_length, bool unknown_blocks, int cell_voxels,
                                          double clearance) {
  const int c = std::max(1, cell_voxels);
  const double res = map.resolution() * c;  // the search runs on cells of c^3 voxels
  auto cellOf = [&](const Vec3& p) {
    return Vec3i(int(std::floor(p.x() / res)), int(std::floor(p.y() / res)), int(std::floor(p.z() / res)));
  };
  auto cellCenter = [&](const Vec3i& k) { return Vec3((k.cast<double>() + Vec3::Constant(0.5)) * res); };
  const Vec3i ka = cellOf(a), kb = cellOf(b);
  const double direct = (b - a).norm();
  if (direct > max_length) return std::nullopt;
  if (ka == kb) {
    if (!tubeOfSight(map, a, b, clearance, unknown_blocks)) return std::nullopt;
    return std::vector<Vec3>{a, b};
  }
  // Every voxel on a path of length <= L lies within (L - |ab|)/2 of the segment's box. One
  // extra layer of voxels forms a border that is never passable, so moves need no bounds check.
  const double slack = 0.5 * (max_length - direct) + res;
  Vec3i lo, hi;
  for (int i = 0; i < 3; ++i) {
    lo[i] = int(std::floor((std::min(a[i], b[i]) - slack) / res)) - 1;
    hi[i] = int(std::floor((std::max(a[i], b[i]) + slack) / res)) + 1;
  }
  const Vec3i dims = hi - lo + Vec3i::Ones();
  const size_t n = size_t(dims.x()) * dims.y() * dims.z();
  if (n > 4'000'000) return std::nullopt;  // guard against absurd max_length
  const int64_t sx = 1, sy = dims.x(), sz = int64_t(dims.x()) * dims.y();
  auto idx = [&](const Vec3i& k) {
    const Vec3i r = k - lo;
    return size_t(r.z() * sz + r.y() * sy + r.x());
  };
  auto keyOfIndex = [&](size_t i) {
    return Vec3i(lo.x() + int(i % size_t(sy)), lo.y() + int((i / size_t(sy)) % size_t(dims.y())),
                 lo.z() + int(i / size_t(sz)));
  };

  // Scratch arrays are reused between calls (page faults of fresh ones cost more than the
  // search) and reset lazily by a generation stamp, so a call pays only for what it touches.
  struct Scratch {
    std::vector<uint32_t> stamp;
    std::vector<float> g;
    std::vector<int> parent;
    std::vector<signed char> pass;  // -1 not asked yet, 0 blocked, 1 passable
    std::vector<char> closed;
    uint32_t generation = 0;
  };
  thread_local Scratch sc;
  if (sc.stamp.size() < n) {
    sc.stamp.assign(n, 0);
    sc.g.resize(n);
    sc.parent.resize(n);
    sc.pass.resize(n);
    sc.closed.resize(n);
    sc.generation = 0;
  }
  if (++sc.generation == 0) {  // wrapped: clear all stamps once
    std::fill(sc.stamp.begin(), sc.stamp.end(), 0);
    sc.generation = 1;
  }
  constexpr float kInf = std::numeric_limits<float>::infinity();
  auto touch = [&](size_t i) {
    if (sc.stamp[i] != sc.generation) {
      sc.stamp[i] = sc.generation;
      sc.g[i] = kInf;
      sc.parent[i] = -1;
      sc.pass[i] = -1;
      sc.closed[i] = 0;
    }
  };
  const size_t goal = idx(kb), origin = idx(ka);
  // Map lookups are the other cost: each voxel is asked at most once. The border layer of the
  // box is never passable.
  auto passable = [&](size_t i) {
    touch(i);
    signed char& cp = sc.pass[i];
    if (cp < 0) {
      const Vec3i k = keyOfIndex(i);
      const bool border = (k.array() == lo.array()).any() || (k.array() == hi.array()).any();
      bool ok = !border;
      // A cell is passable when all its voxels are (the end cells always are).
      if (ok && i != goal && i != origin)
        for (int z = 0; z < c && ok; ++z)
          for (int y = 0; y < c && ok; ++y)
            for (int x = 0; x < c && ok; ++x) {
              const VoxelState st = map.state(k * c + Vec3i(x, y, z));
              ok = st == VoxelState::Free || (!unknown_blocks && st == VoxelState::Unknown);
            }
      cp = ok ? 1 : 0;
    }
    return cp == 1;
  };

  // The 26 moves; a diagonal move also needs each of its axis-aligned sub-moves passable, so
  // paths never squeeze between voxels that touch at an edge or corner.
  struct Move {
    int64_t delta;
    float cost;
    int dx, dy, dz;
    std::vector<int64_t> sub;
  };
  std::vector<Move> moves;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (!dx && !dy && !dz) continue;
        Move m{dx * sx + dy * sy + dz * sz, float(res * std::sqrt(double(dx * dx + dy * dy + dz * dz))),
               dx, dy, dz, {}};
        for (int mask = 1; mask < 7; ++mask) {
          const int ex = (mask & 1) ? dx : 0, ey = (mask & 2) ? dy : 0, ez = (mask & 4) ? dz : 0;
          const int64_t d = ex * sx + ey * sy + ez * sz;
          if (d != 0 && d != m.delta && std::find(m.sub.begin(), m.sub.end(), d) == m.sub.end()) m.sub.push_back(d);
        }
        moves.push_back(std::move(m));
      }

  const Vec3i gk = kb - lo;
  auto h = [&](int x, int y, int z) {
    const double ddx = x - gk.x(), ddy = y - gk.y(), ddz = z - gk.z();
    return float(res * std::sqrt(ddx * ddx + ddy * ddy + ddz * ddz));
  };
  auto& g = sc.g;
  auto& parent = sc.parent;
  auto& closed = sc.closed;
  using Item = std::pair<float, size_t>;  // f, index; ties broken by index: deterministic
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  // Path length is measured between voxel centres, plus the offsets of a and b from theirs.
  const double end_offsets = (a - cellCenter(ka)).norm() + (b - cellCenter(kb)).norm();
  const float budget = float(max_length - end_offsets) + 1e-5f;
  touch(origin);
  g[origin] = 0.f;
  {
    const Vec3i r = ka - lo;
    open.push({h(r.x(), r.y(), r.z()), origin});
  }
  bool found = false;
  while (!open.empty()) {
    const auto [f, i] = open.top();
    open.pop();
    if (closed[i]) continue;
    if (f > budget) break;
    closed[i] = 1;
    if (i == goal) {
      found = true;
      break;
    }
    const int x = int(i % size_t(sy)), y = int((i / size_t(sy)) % size_t(dims.y())), z = int(i / size_t(sz));
    for (const Move& m : moves) {
      const size_t ni = size_t(int64_t(i) + m.delta);
      if (!passable(ni) || closed[ni]) continue;
      bool ok = true;
      for (int64_t d : m.sub)
        if (!passable(size_t(int64_t(i) + d))) {
          ok = false;
          break;
        }
      if (!ok) continue;
      const float ng = g[i] + m.cost;
      if (ng < g[ni]) {
        const float nf = ng + h(x + m.dx, y + m.dy, z + m.dz);
        if (nf > budget) continue;
        g[ni] = ng;
        parent[ni] = int(i);
        open.push({nf, ni});
      }
    }
  }
  if (!found) return std::nullopt;
  std::vector<Vec3> pts{b};
  for (int i = parent[goal]; i >= 0; i = parent[size_t(i)])
    pts.push_back(size_t(i) == origin ? a : cellCenter(keyOfIndex(size_t(i))));
  std::reverse(pts.begin(), pts.end());
  std::vector<Vec3> out = shortcutPolyline(map, pts, unknown_blocks, clearance);
  if (polylineLength(out) > max_length + 1e-9 || !polylineClear(map, out, unknown_blocks))
    return std::nullopt;
  return out;
}

}  // namespace ussnav
