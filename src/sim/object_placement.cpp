// Furnishing: rules from the object table, room by room, each object tried at random poses of
// its placement mode until one passes every check: inside the room clear of the walls, out of
// every door's clear zone, apart from other objects, under the floor-cover cap, and leaving
// the room navigable (a 2-D grid, inflated by the UAV radius, still joins all doors, keeps
// most of its free area, and comes within kApproach of every object).

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "floorplan_internal.hpp"
#include "ussnav/sim/layout_geometry.hpp"
#include "ussnav/sim/object_table.hpp"

namespace ussnav::floorplan {

namespace {

constexpr double kCell = 0.1;               // m, navigability grid
constexpr double kObjectGap = 0.05;         // m between two floor objects
constexpr double kWallGap = 0.03;           // m between an object and a wall face
constexpr double kMaxFloorCover = 0.35;     // of the room's area, floor-standing footprints
constexpr double kKeepReachable = 0.55;     // of the empty room's free cells
constexpr double kApproach = 0.6;           // m: reachable space this close to every object
constexpr int kTries = 40;

// The room on a grid: static free cells (inside, clear of walls by the UAV radius) and a count
// of objects blocking each cell.
class RoomGrid {
 public:
  RoomGrid(const Room& room, double wall_clear, double inflate) : poly_(room.polygon), inflate_(inflate) {
    Vec2 lo = poly_[0], hi = poly_[0];
    for (const auto& p : poly_) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    origin_ = lo;
    nx_ = int(std::ceil((hi.x() - lo.x()) / kCell));
    ny_ = int(std::ceil((hi.y() - lo.y()) / kCell));
    free_.assign(size_t(nx_) * ny_, 0);
    depth_.assign(free_.size(), 0.0);
    blocked_.assign(free_.size(), 0);
    for (int i = 0; i < int(free_.size()); ++i) {
      const Vec2 c = center(i);
      if (!pointInPolygon(c, poly_)) continue;
      depth_[i] = distanceToBoundary(c, poly_);
      free_[i] = depth_[i] >= wall_clear;
    }
  }
  int size() const { return int(free_.size()); }
  Vec2 center(int i) const { return origin_ + Vec2((i % nx_ + 0.5) * kCell, (i / nx_ + 0.5) * kCell); }
  bool isFree(int i) const { return free_[i] && blocked_[i] == 0; }
  bool staticFree(int i) const { return free_[i]; }
  double depth(int i) const { return depth_[i]; }
  // Static free cell nearest p (within 0.5 m), or -1.
  int nearestFree(const Vec2& p) const {
    int best = -1;
    double bd = 0.5;
    forCellsNear(p, 0.5, [&](int i) {
      const double d = (center(i) - p).norm();
      if (free_[i] && d < bd) bd = d, best = i;
    });
    return best;
  }
  template <class F>
  void forCellsNear(const Vec2& p, double r, F f) const {
    const int i0 = std::max(0, int(std::floor((p.x() - r - origin_.x()) / kCell)));
    const int i1 = std::min(nx_ - 1, int(std::floor((p.x() + r - origin_.x()) / kCell)));
    const int j0 = std::max(0, int(std::floor((p.y() - r - origin_.y()) / kCell)));
    const int j1 = std::min(ny_ - 1, int(std::floor((p.y() + r - origin_.y()) / kCell)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) f(j * nx_ + i);
  }
  // Cells whose centre is within `dist` of the box footprint.
  std::vector<int> cellsNear(const OrientedBox& b, double dist) const {
    std::vector<int> out;
    const double r = b.half_extents.head<2>().norm() + dist;
    forCellsNear(Vec2(b.center.x(), b.center.y()), r, [&](int i) {
      if (distanceToFootprint(center(i), b) <= dist) out.push_back(i);
    });
    return out;
  }
  void block(const OrientedBox& b, int delta) {
    for (int i : cellsNear(b, inflate_)) blocked_[i] += delta;
  }
  // Cells reachable from `seed` (4-neighbour) over free cells.
  std::vector<char> reach(int seed) const {
    std::vector<char> seen(free_.size(), 0);
    if (seed < 0 || !isFree(seed)) return seen;
    std::deque<int> q{seed};
    seen[seed] = 1;
    while (!q.empty()) {
      const int c = q.front();
      q.pop_front();
      const int i = c % nx_, j = c / nx_;
      const int nb[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
      for (const auto& n : nb) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= nx_ || n[1] >= ny_) continue;
        const int k = n[1] * nx_ + n[0];
        if (!seen[k] && isFree(k)) seen[k] = 1, q.push_back(k);
      }
    }
    return seen;
  }

 private:
  std::vector<Vec2> poly_;
  double inflate_;
  Vec2 origin_;
  int nx_ = 0, ny_ = 0;
  std::vector<char> free_;
  std::vector<double> depth_;
  std::vector<int> blocked_;
};

// Door seeds: a free cell half the clear depth in front of each of the room's doors.
std::vector<int> doorSeeds(const World& w, const Room& room, const RoomGrid& grid) {
  std::vector<int> seeds;
  for (const auto& d : w.doors) {
    if (d.room_a != room.id && d.room_b != room.id) continue;
    const OrientedBox z = doorClearZone(w, d, room.id);
    const int s = grid.nearestFree(Vec2(z.center.x(), z.center.y()));
    if (s >= 0) seeds.push_back(s);
  }
  return seeds;
}

class RoomFurnisher {
 public:
  RoomFurnisher(World& w, const Room& room, const GeneratorParams& p, Rng& rng)
      : w_(w), room_(room), p_(p), rng_(rng),
        margin_(0.5 * p.wall_thickness + kWallGap),
        grid_(room, 0.5 * p.wall_thickness + p.uav_radius, p.uav_radius + 0.02) {
    area_ = std::abs(polygonArea(room.polygon));
    for (const auto& d : w.doors)
      if (d.room_a == room.id || d.room_b == room.id) zones_.push_back(doorClearZone(w, d, room.id));
    seeds_ = doorSeeds(w, room, grid_);
    if (!seeds_.empty()) {
      const auto seen = grid_.reach(seeds_[0]);
      base_reach_ = int(std::count(seen.begin(), seen.end(), 1));
    }
    Vec2 lo = room.polygon[0], hi = lo;
    for (const auto& q : room.polygon) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    long_axis_yaw_ = (hi.x() - lo.x()) >= (hi.y() - lo.y()) ? 0.0 : kPi / 2;
    for (int i = 0; i < grid_.size(); ++i)
      if (grid_.staticFree(i)) free_cells_.push_back(i);
    int deepest = -1;
    for (int i : free_cells_)
      if (deepest < 0 || grid_.depth(i) > grid_.depth(deepest) + 1e-9) deepest = i;
    middle_ = deepest >= 0 ? grid_.center(deepest) : polygonCentroid(room.polygon);
  }

  void run() {
    if (seeds_.empty()) return;  // a room without doors stays empty (never generated)
    for (const auto& rule : rulesFor(p_.style, room_.type)) {
      const ObjectCategory* cat = findCategory(rule.category);
      if (!cat) continue;
      if (rule.per_parent) {
        std::vector<size_t> parents;
        for (size_t i = 0; i < placed_.size(); ++i)
          if (isParent(*cat, placed_[i].category)) parents.push_back(i);
        for (size_t pi : parents) {
          if (!rng_.bernoulli(rule.probability)) continue;
          const int k = rng_.uniformInt(rule.min_count, rule.max_count);
          for (int n = 0; n < k; ++n) place(*cat, int(pi));
        }
        continue;
      }
      if (!rng_.bernoulli(rule.probability)) continue;
      int hi = rule.max_count;
      if (rule.m2_per_extra > 0) hi = std::clamp(int(area_ / rule.m2_per_extra), rule.max_count, 8);
      const int k = rng_.uniformInt(rule.min_count, std::max(rule.min_count, hi));
      for (int n = 0; n < k; ++n) place(*cat, -1);
    }
    for (auto& o : placed_) {
      o.id = int(w_.objects.size()) + 1;
      w_.objects.push_back(o);
    }
  }

 private:
  static bool isParent(const ObjectCategory& cat, const std::string& name) {
    return std::find(cat.parents.begin(), cat.parents.end(), name) != cat.parents.end();
  }

  double cm(double v) { return std::round(v * 100.0) / 100.0; }

  bool place(const ObjectCategory& cat, int parent) {
    Vec3 size(cm(cat.size.x() * rng_.uniform(0.92, 1.08)), cm(cat.size.y() * rng_.uniform(0.92, 1.08)),
              cm(cat.size.z() * rng_.uniform(0.92, 1.08)));
    for (int t = 0; t < kTries; ++t) {
      // Half way through, try a smaller footprint (a big table in a small room).
      if (t == kTries / 2 && cat.placement != Placement::OnTop) size.head<2>() *= 0.8;
      int par = parent;
      if (par < 0 && !cat.parents.empty()) {
        std::vector<int> cand;
        for (size_t i = 0; i < placed_.size(); ++i)
          if (isParent(cat, placed_[i].category)) cand.push_back(int(i));
        if (cand.empty()) return false;
        par = cand[rng_.uniformInt(0, int(cand.size()) - 1)];
      }
      const std::optional<OrientedBox> b = candidate(cat, size, par);
      if (!b || !fits(cat, *b)) continue;
      Object o;
      o.category = cat.name;
      o.room_id = room_.id;
      o.box = *b;
      placed_.push_back(o);
      if (cat.placement != Placement::OnTop) grid_.block(o.box, +1);
      return true;
    }
    return false;
  }

  OrientedBox boxAt(const Vec2& c, double z_bottom, const Vec3& size, double yaw) const {
    OrientedBox b;
    b.center = Vec3(c.x(), c.y(), z_bottom + 0.5 * size.z());
    b.half_extents = 0.5 * size;
    b.yaw = wrapAngle(yaw);
    return b;
  }

  std::optional<OrientedBox> candidate(const ObjectCategory& cat, const Vec3& size, int parent) {
    const auto& poly = room_.polygon;
    const double floor = room_.floor_z;
    switch (cat.placement) {
      case Placement::Wall:
      case Placement::Corner:
      case Placement::Mounted: {
        // An edge long enough, picked with probability proportional to its length.
        double total = 0;
        std::vector<double> lens(poly.size());
        for (size_t i = 0; i < poly.size(); ++i) {
          lens[i] = (poly[(i + 1) % poly.size()] - poly[i]).norm();
          if (lens[i] < size.x() + 2 * margin_) lens[i] = 0;
          total += lens[i];
        }
        if (total <= 0) return std::nullopt;
        double pick = rng_.uniform(0.0, total);
        size_t e = 0;
        while (e + 1 < poly.size() && pick >= lens[e]) pick -= lens[e], ++e;
        if (lens[e] <= 0) return std::nullopt;
        const Vec2 a = poly[e], d = (poly[(e + 1) % poly.size()] - a) / lens[e];
        const Vec2 n(-d.y(), d.x());  // CCW polygon: the interior is on the left
        const double lo = margin_ + 0.5 * size.x() + 0.005, hi = lens[e] - lo;
        double u = rng_.uniform(lo, hi);
        if (cat.placement == Placement::Corner) u = rng_.bernoulli(0.5) ? lo : hi;
        const Vec2 c = a + d * u + n * (margin_ + 0.5 * size.y() + 0.005);
        const double z0 = floor + (cat.placement == Placement::Mounted ? cat.mount_z : 0.0);
        return boxAt(c, z0, size, std::atan2(d.y(), d.x()));
      }
      case Placement::Center: {
        const Vec2 c = middle_ + Vec2(rng_.uniform(-0.5, 0.5), rng_.uniform(-0.5, 0.5));
        return boxAt(c, floor, size, long_axis_yaw_ + (rng_.bernoulli(0.5) ? kPi : 0.0));
      }
      case Placement::Free: {
        if (free_cells_.empty()) return std::nullopt;
        const int cell = free_cells_[rng_.uniformInt(0, int(free_cells_.size()) - 1)];
        const Vec2 c = grid_.center(cell) + Vec2(rng_.uniform(-0.05, 0.05), rng_.uniform(-0.05, 0.05));
        const double yaw = rng_.uniformInt(0, 3) * kPi / 2 + deg2rad(cat.yaw_jitter_deg) * rng_.uniform(-1.0, 1.0);
        return boxAt(c, floor, size, yaw);
      }
      case Placement::OnTop: {
        const OrientedBox& pb = placed_[parent].box;
        const double room_x = 2 * pb.half_extents.x() - 0.04, room_y = 2 * pb.half_extents.y() - 0.04;
        bool turned = false;  // a quarter turn may make it fit (a monitor across a narrow shelf)
        if (size.x() > room_x || size.y() > room_y) {
          if (size.y() > room_x || size.x() > room_y) return std::nullopt;
          turned = true;
        }
        const double ex = turned ? size.y() : size.x(), ey = turned ? size.x() : size.y();
        const double rx = std::max(0.0, pb.half_extents.x() - 0.5 * ex - 0.02);
        const double ry = std::max(0.0, pb.half_extents.y() - 0.5 * ey - 0.02);
        const Vec2 l(rng_.uniform(-rx, rx), rng_.uniform(-ry, ry));
        const double c = std::cos(pb.yaw), sn = std::sin(pb.yaw);
        const Vec2 at(pb.center.x() + c * l.x() - sn * l.y(), pb.center.y() + sn * l.x() + c * l.y());
        return boxAt(at, pb.center.z() + pb.half_extents.z(), size, pb.yaw + (turned ? kPi / 2 : 0.0));
      }
      case Placement::Around:
      case Placement::Front: {
        const OrientedBox& pb = placed_[parent].box;
        const double px = pb.half_extents.x(), py = pb.half_extents.y();
        const double off = 0.5 * size.y() + kObjectGap + 0.01;
        int side = 0;  // 0: +y (the parent's front), 1: -y, 2: +x, 3: -x
        if (cat.placement == Placement::Around) {
          const double pick = rng_.uniform(0.0, 4 * px + 4 * py);
          side = pick < 2 * px ? 0 : pick < 4 * px ? 1 : pick < 4 * px + 2 * py ? 2 : 3;
        }
        const double along_x = std::max(0.0, px - 0.5 * size.x()), along_y = std::max(0.0, py - 0.5 * size.x());
        Vec2 l;
        double rel = 0;  // chair yaw relative to the parent, so the chair faces it
        switch (side) {
          case 0: l = Vec2(rng_.uniform(-along_x, along_x) * (cat.placement == Placement::Front ? 0.3 : 1.0), py + off); rel = kPi; break;
          case 1: l = Vec2(rng_.uniform(-along_x, along_x), -(py + off)); rel = 0; break;
          case 2: l = Vec2(px + off, rng_.uniform(-along_y, along_y)); rel = kPi / 2; break;
          default: l = Vec2(-(px + off), rng_.uniform(-along_y, along_y)); rel = -kPi / 2; break;
        }
        const double c = std::cos(pb.yaw), sn = std::sin(pb.yaw);
        const Vec2 at(pb.center.x() + c * l.x() - sn * l.y(), pb.center.y() + sn * l.x() + c * l.y());
        return boxAt(at, floor, size, pb.yaw + rel);
      }
    }
    return std::nullopt;
  }

  bool fits(const ObjectCategory& cat, const OrientedBox& b) {
    const bool on_top = cat.placement == Placement::OnTop;
    const bool floor_standing = !on_top && cat.placement != Placement::Mounted;
    if (b.center.z() + b.half_extents.z() > room_.ceiling_z - 0.05) return false;
    if (!on_top) {
      if (!footprintInsidePolygon(b, room_.polygon, margin_)) return false;
      for (const auto& z : zones_)
        if (footprintsOverlap(b, z)) return false;
    }
    for (const auto& o : placed_)
      if (boxesOverlap(b, o.box, on_top ? 0.02 : kObjectGap)) return false;
    if (floor_standing) {
      double cover = 4 * b.half_extents.x() * b.half_extents.y();
      for (const auto& o : placed_)
        if (o.box.center.z() - o.box.half_extents.z() <= room_.floor_z + 1e-6)
          cover += 4 * o.box.half_extents.x() * o.box.half_extents.y();
      if (cover > kMaxFloorCover * area_) return false;
    }
    return navigable(b, !on_top);
  }

  // With `b` added: all doors still joined, most of the room still reachable, and every
  // object still approachable (objects on top of others are not obstacles of their own, but
  // must be approachable too: a laptop at the back of a desk in a corner is not).
  bool navigable(const OrientedBox& b, bool obstacle) {
    if (obstacle) grid_.block(b, +1);
    const auto seen = grid_.reach(seeds_[0]);
    bool ok = int(std::count(seen.begin(), seen.end(), 1)) >= kKeepReachable * base_reach_;
    for (size_t s = 1; ok && s < seeds_.size(); ++s) ok = seen[seeds_[s]];
    auto approachable = [&](const OrientedBox& ob) {
      for (int i : grid_.cellsNear(ob, kApproach))
        if (seen[i]) return true;
      return false;
    };
    ok = ok && approachable(b);
    for (size_t i = 0; ok && i < placed_.size(); ++i) ok = approachable(placed_[i].box);
    if (obstacle) grid_.block(b, -1);
    return ok;
  }

  World& w_;
  const Room& room_;
  const GeneratorParams& p_;
  Rng& rng_;
  double margin_;
  RoomGrid grid_;
  double area_ = 0;
  std::vector<OrientedBox> zones_;
  std::vector<int> seeds_;
  int base_reach_ = 0;
  double long_axis_yaw_ = 0;
  std::vector<int> free_cells_;
  Vec2 middle_;
  std::vector<Object> placed_;
};

}  // namespace

void furnish(const GeneratorParams& params, Rng& rng, World& world) {
  // Objects are appended to world.objects as each room finishes; rooms are read by index so
  // that growing the object list never invalidates the room being furnished.
  for (size_t r = 0; r < world.rooms.size(); ++r) {
    const Room room = world.rooms[r];
    RoomFurnisher(world, room, params, rng).run();
  }
}

Pose chooseStart(const World& world, const std::string& room_type, const GeneratorParams& params) {
  const Room* best = nullptr;
  for (int pass = 0; pass < 2 && !best; ++pass)
    for (const auto& r : world.rooms)
      if ((pass == 1 || r.type == room_type) &&
          (!best || std::abs(polygonArea(r.polygon)) > std::abs(polygonArea(best->polygon)) + 1e-9))
        best = &r;
  Pose pose;
  if (!best) return pose;
  RoomGrid grid(*best, 0.5 * params.wall_thickness + params.uav_radius, params.uav_radius + 0.02);
  std::vector<const Object*> objs;
  for (const auto& o : world.objects)
    if (o.room_id == best->id) objs.push_back(&o), grid.block(o.box, +1);
  const auto seeds = doorSeeds(world, *best, grid);
  const auto seen = grid.reach(seeds.empty() ? -1 : seeds[0]);
  Vec2 lo = best->polygon[0], hi = lo;
  for (const auto& q : best->polygon) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const Vec2 mid = 0.5 * (lo + hi);
  std::vector<double> clear(grid.size(), -1.0);
  double top = -1.0;
  for (int i = 0; i < grid.size(); ++i) {
    if (!(seeds.empty() ? grid.isFree(i) : seen[i])) continue;
    double c = grid.depth(i) - 0.5 * params.wall_thickness;
    for (const Object* o : objs) c = std::min(c, distanceToFootprint(grid.center(i), o->box));
    clear[i] = c;
    top = std::max(top, c);
  }
  int pick = -1;
  for (int i = 0; i < grid.size(); ++i)
    if (clear[i] >= top - 0.05 && clear[i] >= 0 &&
        (pick < 0 || (grid.center(i) - mid).norm() < (grid.center(pick) - mid).norm() - 1e-9))
      pick = i;
  const Vec2 p = pick >= 0 ? grid.center(pick) : polygonCentroid(best->polygon);
  pose.position = Vec3(p.x(), p.y(), best->floor_z + params.flight_height);
  pose.yaw = (hi.x() - lo.x()) >= (hi.y() - lo.y()) ? 0.0 : kPi / 2;
  return pose;
}

}  // namespace ussnav::floorplan
