#include "world_checks.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

#include "ussnav/sim/layout_geometry.hpp"

namespace ussnav::test {

int roomsReachableByDoors(const World& w) {
  if (w.rooms.empty()) return 0;
  std::set<int> seen{w.rooms[0].id};
  std::deque<int> q{w.rooms[0].id};
  while (!q.empty()) {
    const int r = q.front();
    q.pop_front();
    for (const auto& d : w.doors) {
      const int other = d.room_a == r ? d.room_b : d.room_b == r ? d.room_a : -1;
      if (other > 0 && seen.insert(other).second) q.push_back(other);
    }
  }
  return int(seen.size());
}

std::string doorProblem(const World& w, const Door& d) {
  const Room* a = w.room(d.room_a);
  const Room* b = w.room(d.room_b);
  if (!a || !b) return "door does not join two rooms";
  for (const auto& wl : w.walls) {
    if (pointSegmentDistance(d.center, wl.a, wl.b) > 1e-6) continue;
    const Vec2 dir = (wl.b - wl.a).normalized(), n(-dir.y(), dir.x());
    const Vec2 p = d.center + 0.2 * n, q = d.center - 0.2 * n;
    const bool sides = (pointInPolygon(p, a->polygon) && pointInPolygon(q, b->polygon)) ||
                       (pointInPolygon(q, a->polygon) && pointInPolygon(p, b->polygon));
    if (!sides) continue;
    const double s = (d.center - wl.a).dot(dir);
    for (const auto& o : wl.openings)
      if (std::abs(0.5 * (o.start + o.end) - s) < 1e-6 && std::abs((o.end - o.start) - d.width) < 1e-6 &&
          std::abs(o.top - d.height) < 1e-6 && o.bottom <= 1e-9)
        return "";
    return "wall between the rooms has no matching opening";
  }
  return "no wall shared by the door's two rooms passes through its centre";
}

int roomOverlapSamples(const World& w) {
  const Aabb b = w.bounds();
  int bad = 0;
  for (double y = std::floor(b.min.y()) + 0.125; y < b.max.y(); y += 0.25)
    for (double x = std::floor(b.min.x()) + 0.125; x < b.max.x(); x += 0.25) {
      int in = 0;
      for (const auto& r : w.rooms) in += pointInPolygon(Vec2(x, y), r.polygon);
      bad += in > 1;
    }
  return bad;
}

Reachability checkReachability(const World& w, double radius, double approach) {
  constexpr double res = 0.05;
  const Aabb b = w.bounds();
  const Vec2 lo(b.min.x(), b.min.y());
  const int nx = int(std::ceil((b.max.x() - lo.x()) / res)), ny = int(std::ceil((b.max.y() - lo.y()) / res));
  auto center = [&](int i, int j) { return Vec2(lo.x() + (i + 0.5) * res, lo.y() + (j + 0.5) * res); };
  std::vector<int> room_of(size_t(nx) * ny, -1);
  std::vector<char> blocked(room_of.size(), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (const Room* r = w.roomAt(center(i, j))) room_of[size_t(j) * nx + i] = r->id;
  auto stamp = [&](const Vec2& p0, const Vec2& p1, double clear) {  // cells near a segment
    const int i0 = std::max(0, int((std::min(p0.x(), p1.x()) - clear - lo.x()) / res));
    const int i1 = std::min(nx - 1, int((std::max(p0.x(), p1.x()) + clear - lo.x()) / res));
    const int j0 = std::max(0, int((std::min(p0.y(), p1.y()) - clear - lo.y()) / res));
    const int j1 = std::min(ny - 1, int((std::max(p0.y(), p1.y()) + clear - lo.y()) / res));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if (pointSegmentDistance(center(i, j), p0, p1) < clear) blocked[size_t(j) * nx + i] = 1;
  };
  // Walls at flight height: solid except where an opening spans it.
  const double z = w.start.position.z();
  for (const auto& wl : w.walls) {
    const double len = (wl.b - wl.a).norm();
    const Vec2 d = (wl.b - wl.a) / len;
    double s = 0;
    std::vector<std::pair<double, double>> gaps;
    for (const auto& o : wl.openings)
      if (o.bottom <= z - wl.z0 && o.top >= z - wl.z0) gaps.emplace_back(o.start, o.end);
    std::sort(gaps.begin(), gaps.end());
    for (const auto& [g0, g1] : gaps) {
      if (g0 > s) stamp(wl.a + d * s, wl.a + d * g0, 0.5 * wl.thickness + radius);
      s = std::max(s, g1);
    }
    if (s < len) stamp(wl.a + d * s, wl.a + d * len, 0.5 * wl.thickness + radius);
  }
  for (const auto& o : w.objects) {
    const Aabb ob = o.box.bounds();
    const int i0 = std::max(0, int((ob.min.x() - radius - lo.x()) / res));
    const int i1 = std::min(nx - 1, int((ob.max.x() + radius - lo.x()) / res));
    const int j0 = std::max(0, int((ob.min.y() - radius - lo.y()) / res));
    const int j1 = std::min(ny - 1, int((ob.max.y() + radius - lo.y()) / res));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if (distanceToFootprint(center(i, j), o.box) < radius) blocked[size_t(j) * nx + i] = 1;
  }
  Reachability out;
  const int si = int((w.start.position.x() - lo.x()) / res), sj = int((w.start.position.y() - lo.y()) / res);
  std::vector<char> seen(room_of.size(), 0);
  if (si >= 0 && sj >= 0 && si < nx && sj < ny) {
    const size_t s = size_t(sj) * nx + si;
    out.start_free = room_of[s] > 0 && !blocked[s];
    if (out.start_free) {
      std::deque<size_t> q{s};
      seen[s] = 1;
      while (!q.empty()) {
        const size_t c = q.front();
        q.pop_front();
        const int i = int(c % nx), j = int(c / nx);
        const int nb[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
        for (const auto& n : nb) {
          if (n[0] < 0 || n[1] < 0 || n[0] >= nx || n[1] >= ny) continue;
          const size_t k = size_t(n[1]) * nx + n[0];
          if (!seen[k] && !blocked[k] && room_of[k] > 0) seen[k] = 1, q.push_back(k);
        }
      }
    }
  }
  std::set<int> rooms_hit;
  for (size_t c = 0; c < seen.size(); ++c)
    if (seen[c]) rooms_hit.insert(room_of[c]);
  for (const auto& r : w.rooms)
    if (!rooms_hit.count(r.id)) out.unreachable_rooms.push_back(r.id);
  for (const auto& o : w.objects) {
    bool ok = false;
    const Aabb ob = o.box.bounds();
    const int i0 = std::max(0, int((ob.min.x() - approach - lo.x()) / res));
    const int i1 = std::min(nx - 1, int((ob.max.x() + approach - lo.x()) / res));
    const int j0 = std::max(0, int((ob.min.y() - approach - lo.y()) / res));
    const int j1 = std::min(ny - 1, int((ob.max.y() + approach - lo.y()) / res));
    for (int j = j0; j <= j1 && !ok; ++j)
      for (int i = i0; i <= i1 && !ok; ++i)
        ok = seen[size_t(j) * nx + i] && distanceToFootprint(center(i, j), o.box) <= approach;
    if (!ok) out.unreachable_objects.push_back(o.id);
  }
  return out;
}

}  // namespace ussnav::test
