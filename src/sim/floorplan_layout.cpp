// Plan -> rooms, walls and doors. Rooms are unions of decimetre rectangles; every boundary
// between two different owners (rooms or the outside) becomes one wall per owner pair and
// straight run, so a door always lies on a wall that exactly two rooms share.

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>

#include "floorplan_internal.hpp"

namespace ussnav::floorplan {

namespace {

constexpr double kCornerClear = 0.35;  // m between a door jamb and the end of its wall
constexpr double kMinDoor = 0.9, kMaxDoor = 1.2, kDoorHeight = 2.1;
constexpr double kDoorSpacing = 0.6;   // m between two openings in one wall

Vec2 dm(int x, int y) { return Vec2(x * 0.1, y * 0.1); }

std::vector<int> uniqueSorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

bool rectCovers(const RectDm& r, double cx, double cy) {
  return cx > r.x0 && cx < r.x1 && cy > r.y0 && cy < r.y1;
}

// Boundary runs between owners on the lattice of all rectangle coordinates.
std::vector<PlanWall> planWalls(const Plan& plan) {
  std::vector<int> xs, ys;
  for (const auto& r : plan.rooms)
    for (const auto& q : r.rects) xs.insert(xs.end(), {q.x0, q.x1}), ys.insert(ys.end(), {q.y0, q.y1});
  xs = uniqueSorted(xs);
  ys = uniqueSorted(ys);
  const int nx = int(xs.size()) - 1, ny = int(ys.size()) - 1;
  std::vector<int> owner(size_t(nx) * ny, -1);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double cx = 0.5 * (xs[i] + xs[i + 1]), cy = 0.5 * (ys[j] + ys[j + 1]);
      for (size_t k = 0; k < plan.rooms.size() && owner[size_t(i) * ny + j] < 0; ++k)
        for (const auto& q : plan.rooms[k].rects)
          if (rectCovers(q, cx, cy)) owner[size_t(i) * ny + j] = int(k) + 1;
    }
  auto own = [&](int i, int j) { return (i < 0 || j < 0 || i >= nx || j >= ny) ? -1 : owner[size_t(i) * ny + j]; };
  std::vector<PlanWall> out;
  // Runs along one lattice line: `pairAt(k)` gives the owner pair of the k-th edge on it.
  auto emitRuns = [&](int count, auto pairAt, auto point) {
    int k = 0;
    while (k < count) {
      const auto pr = pairAt(k);
      if (pr.first == pr.second) { ++k; continue; }
      int e = k;
      while (e + 1 < count && pairAt(e + 1) == pr) ++e;
      PlanWall w;
      w.room_a = std::min(pr.first, pr.second);
      w.room_b = std::max(pr.first, pr.second);
      w.a = point(k);
      w.b = point(e + 1);
      out.push_back(w);
      k = e + 1;
    }
  };
  for (int i = 0; i <= nx; ++i)
    emitRuns(ny, [&](int j) { return std::make_pair(own(i - 1, j), own(i, j)); },
             [&](int j) { return dm(xs[i], ys[j]); });
  for (int j = 0; j <= ny; ++j)
    emitRuns(nx, [&](int i) { return std::make_pair(own(i, j - 1), own(i, j)); },
             [&](int i) { return dm(xs[i], ys[j]); });
  return out;
}

class DoorMaker {
 public:
  DoorMaker(World& w, std::vector<PlanWall>& walls, Rng& rng) : w_(w), walls_(walls), rng_(rng) {}

  // Longest straight wall the two rooms share (0 when they do not touch).
  double sharedLength(int ra, int rb) const {
    double best = 0;
    for (const auto& pw : walls_)
      if (pw.room_a == std::min(ra, rb) && pw.room_b == std::max(ra, rb))
        best = std::max(best, (pw.b - pw.a).norm());
    return best;
  }
  bool adjacent(int ra, int rb) const { return sharedLength(ra, rb) >= kMinDoor + 2 * kCornerClear - 1e-9; }

  bool add(int ra, int rb) {
    std::vector<int> cand;
    double total = 0;
    for (size_t i = 0; i < walls_.size(); ++i) {
      const auto& pw = walls_[i];
      const double len = (pw.b - pw.a).norm();
      if (pw.room_a == std::min(ra, rb) && pw.room_b == std::max(ra, rb) && len >= kMinDoor + 2 * kCornerClear - 1e-9) {
        cand.push_back(int(i));
        total += len;
      }
    }
    if (cand.empty()) return false;
    const double want = kMinDoor + 0.05 * rng_.uniformInt(0, int(std::lround((kMaxDoor - kMinDoor) / 0.05)));
    for (int attempt = 0; attempt < 16; ++attempt) {
      double pick = rng_.uniform(0.0, total);
      size_t c = 0;
      while (c + 1 < cand.size() && pick > (walls_[cand[c]].b - walls_[cand[c]].a).norm())
        pick -= (walls_[cand[c]].b - walls_[cand[c]].a).norm(), ++c;
      PlanWall& pw = walls_[cand[c]];
      const double len = (pw.b - pw.a).norm();
      const double width = std::min(want, len - 2 * kCornerClear);
      const double half = 0.5 * width;
      // Door centres on a 5 cm lattice keep the JSON short and the picture tidy.
      const double s = std::round(rng_.uniform(kCornerClear + half, len - kCornerClear - half) * 20.0) / 20.0;
      if (s - half < kCornerClear - 1e-9 || s + half > len - kCornerClear + 1e-9) continue;
      Wall& wall = w_.walls[pw.world_wall];
      const double along = s + 0.5 * wall.thickness;  // the world wall starts half a thickness early
      bool clash = false;
      for (const auto& o : wall.openings)
        if (along + half + kDoorSpacing > o.start && o.end + kDoorSpacing > along - half) clash = true;
      if (clash) continue;
      Opening op;
      op.start = along - half;
      op.end = along + half;
      op.bottom = 0.0;
      op.top = kDoorHeight;
      wall.openings.push_back(op);
      std::sort(wall.openings.begin(), wall.openings.end(),
                [](const Opening& x, const Opening& y) { return x.start < y.start; });
      Door d;
      d.id = int(w_.doors.size()) + 1;
      d.room_a = ra;
      d.room_b = rb;
      d.center = pw.a + (pw.b - pw.a).normalized() * s;
      d.width = width;
      d.height = kDoorHeight;
      w_.doors.push_back(d);
      return true;
    }
    return false;
  }

 private:
  World& w_;
  std::vector<PlanWall>& walls_;
  Rng& rng_;
};

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<Vec2> outlineDm(const std::vector<RectDm>& rects) {
  std::vector<int> xs, ys;
  for (const auto& q : rects) xs.insert(xs.end(), {q.x0, q.x1}), ys.insert(ys.end(), {q.y0, q.y1});
  xs = uniqueSorted(xs);
  ys = uniqueSorted(ys);
  const int nx = int(xs.size()) - 1, ny = int(ys.size()) - 1;
  auto covered = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= nx || j >= ny) return false;
    const double cx = 0.5 * (xs[i] + xs[i + 1]), cy = 0.5 * (ys[j] + ys[j + 1]);
    return std::any_of(rects.begin(), rects.end(), [&](const RectDm& r) { return rectCovers(r, cx, cy); });
  };
  using P = std::pair<int, int>;
  std::map<P, P> next;  // directed boundary edges, interior on the left
  auto edge = [&](P a, P b) {
    if (!next.emplace(a, b).second) throw std::logic_error("floor plan: room outline touches itself");
  };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      if (!covered(i, j)) continue;
      if (!covered(i, j - 1)) edge({xs[i], ys[j]}, {xs[i + 1], ys[j]});
      if (!covered(i + 1, j)) edge({xs[i + 1], ys[j]}, {xs[i + 1], ys[j + 1]});
      if (!covered(i, j + 1)) edge({xs[i + 1], ys[j + 1]}, {xs[i], ys[j + 1]});
      if (!covered(i - 1, j)) edge({xs[i], ys[j + 1]}, {xs[i], ys[j]});
    }
  std::vector<P> loop;
  const P start = next.begin()->first;
  P cur = start;
  do {
    loop.push_back(cur);
    cur = next.at(cur);
  } while (cur != start && loop.size() <= next.size());
  if (loop.size() != next.size()) throw std::logic_error("floor plan: room is not one simple polygon");
  std::vector<Vec2> poly;
  const size_t n = loop.size();
  for (size_t k = 0; k < n; ++k) {
    const P& a = loop[(k + n - 1) % n];
    const P& b = loop[k];
    const P& c = loop[(k + 1) % n];
    const long cross = long(b.first - a.first) * (c.second - b.second) - long(b.second - a.second) * (c.first - b.first);
    if (cross != 0) poly.push_back(dm(b.first, b.second));
  }
  return poly;
}

void buildStructure(const Plan& plan, const GeneratorParams& params, Rng& rng, World& world) {
  const double t = params.wall_thickness;
  for (size_t k = 0; k < plan.rooms.size(); ++k) {
    Room r;
    r.id = int(k) + 1;
    r.type = plan.rooms[k].type;
    r.name = r.type + " " + std::to_string(r.id);
    std::replace(r.name.begin(), r.name.end(), ' ', '_');
    r.polygon = outlineDm(plan.rooms[k].rects);
    r.floor_z = 0.0;
    r.ceiling_z = params.ceiling_height;
    world.rooms.push_back(std::move(r));
  }
  std::vector<PlanWall> walls = planWalls(plan);
  for (auto& pw : walls) {
    const Vec2 dir = (pw.b - pw.a).normalized();
    Wall w;
    w.a = pw.a - 0.5 * t * dir;
    w.b = pw.b + 0.5 * t * dir;
    w.thickness = t;
    w.z0 = 0.0;
    w.z1 = params.ceiling_height;
    pw.world_wall = int(world.walls.size());
    world.walls.push_back(w);
  }

  DoorMaker doors(world, walls, rng);
  const auto& pol = plan.doors;
  const int n = int(plan.rooms.size());
  auto typeOf = [&](int id) -> const std::string& { return plan.rooms[id - 1].type; };
  auto linked = [&](int a, int b) {
    return std::any_of(world.doors.begin(), world.doors.end(), [&](const Door& d) {
      return (d.room_a == a && d.room_b == b) || (d.room_a == b && d.room_b == a);
    });
  };
  // 1. Every room opens onto the best circulation space it touches.
  for (int id = 1; id <= n; ++id) {
    if (!pol.circulation.empty() && typeOf(id) == pol.circulation[0]) continue;
    for (const auto& ct : pol.circulation) {
      std::vector<int> cand;
      for (int o = 1; o <= n; ++o)
        if (o != id && typeOf(o) == ct && plan.rooms[o - 1].group == plan.rooms[id - 1].group && doors.adjacent(id, o))
          cand.push_back(o);
      if (cand.empty()) continue;
      const int o = cand[rng.uniformInt(0, int(cand.size()) - 1)];
      doors.add(id, o);
      const bool two = std::find(pol.two_door_types.begin(), pol.two_door_types.end(), typeOf(id)) !=
                       pol.two_door_types.end();
      if (two && doors.sharedLength(id, o) >= 5.0 && rng.bernoulli(0.6)) doors.add(id, o);
      break;
    }
  }
  // 2. Style extras between adjacent rooms (kitchen-dining, office-office, corridor-corridor...).
  for (int a = 1; a <= n; ++a)
    for (int b = a + 1; b <= n; ++b) {
      if (!doors.adjacent(a, b)) continue;
      for (const auto& e : pol.extra) {
        const bool match = (typeOf(a) == e.a && typeOf(b) == e.b) || (typeOf(a) == e.b && typeOf(b) == e.a);
        const bool same_group = plan.rooms[a - 1].group == plan.rooms[b - 1].group;
        if (!match || (!same_group && !e.cross_group) || linked(a, b)) continue;
        if (rng.bernoulli(e.probability)) doors.add(a, b);
      }
    }
  // 3. Join what is still apart, preferring a circulation space on one side.
  for (;;) {
    std::vector<int> parent(n + 1);
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& d : world.doors)
      if (d.room_a > 0 && d.room_b > 0) parent[findRoot(parent, d.room_a)] = findRoot(parent, d.room_b);
    std::set<int> roots;
    for (int id = 1; id <= n; ++id) roots.insert(findRoot(parent, id));
    if (roots.size() <= 1) break;
    std::vector<std::tuple<int, int, int>> cand;  // (-score, a, b): best first, then by ids
    for (int a = 1; a <= n; ++a)
      for (int b = a + 1; b <= n; ++b) {
        if (findRoot(parent, a) == findRoot(parent, b) || !doors.adjacent(a, b)) continue;
        int score = 0;
        for (const auto& ct : pol.circulation) score += (typeOf(a) == ct) + (typeOf(b) == ct);
        cand.emplace_back(-score, a, b);
      }
    std::sort(cand.begin(), cand.end());
    bool joined = false;
    for (const auto& [neg, a, b] : cand)
      if ((joined = doors.add(a, b))) break;
    if (!joined) throw std::logic_error("floor plan: rooms cannot be joined by doors");
  }
  std::sort(world.doors.begin(), world.doors.end(), [](const Door& x, const Door& y) { return x.id < y.id; });
}

}  // namespace ussnav::floorplan
