#include "ussnav/episode/flight_path.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>

#include "ussnav/episode/approach.hpp"
#include "ussnav/mapping/inflated_map.hpp"
#include "ussnav/skeleton/graph_search.hpp"
#include "ussnav/skeleton/grid_path.hpp"

namespace ussnav {

namespace {

// Whether a body of `radius` moving straight from a to b stays clear of mapped obstacles.
bool sweepClear(const RollingGrid& grid, const Vec3& a, const Vec3& b, double radius) {
  const int n = std::max(1, int(std::ceil((b - a).norm() / 0.05)));
  for (int i = 1; i <= n; ++i)
    if (grid.isInflatedOccupied(a + (b - a) * (double(i) / n), radius)) return false;
  return true;
}

// Nearest voxel centre with full clearance that the body reaches in a straight line.
std::optional<Vec3> escapePoint(const RollingGrid& grid, const InflatedMap& inflated, const Vec3& from,
                                double body_radius) {
  const double res = grid.resolution();
  const Vec3i c = grid.keyOf(from);
  const int n = int(std::ceil(0.8 / res));
  double best = std::numeric_limits<double>::infinity();
  std::optional<Vec3> out;
  for (int dz = -2; dz <= 2; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        const Vec3 p = grid.centerOf(k);
        const double d = (p - from).norm();
        if (d >= best || d > 0.8 || inflated.state(k) != VoxelState::Free) continue;
        if (!sweepClear(grid, from, p, body_radius)) continue;
        best = d, out = p;
      }
  return out;
}

// Nearest voxel centre within `radius` of p that the inflated map holds Free (p itself when it
// is), or nullopt.
std::optional<Vec3> snapFree(const OccupancyMap& inflated, const Vec3& p, double radius) {
  if (inflated.stateAt(p) != VoxelState::Occupied) return p;
  const double res = inflated.resolution();
  const Vec3i c = inflated.keyOf(p);
  const int n = int(std::ceil(radius / res));
  double best = std::numeric_limits<double>::infinity();
  std::optional<Vec3> out;
  for (int dz = -n; dz <= n; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        const Vec3 q = inflated.centerOf(k);
        const double d = (q - p).norm();
        if (d < best && d <= radius && inflated.state(k) == VoxelState::Free) best = d, out = q;
      }
  return out;
}

// A segment a-b that the inflated map shows blocked, with at least one end outside the window:
// the map knows only the part inside. First a voxel path that treats the space beyond the window
// as passable (checked again when the window gets there); else, with one end inside, a detour
// from that end to where the segment crosses the window's edge (0.3 m inside), keeping the rest
// of the segment when that does not cross what the window shows blocked either (the flight loop
// would reject the path as soon as it is flown, and the same path would come back). The
// polyline runs from a to b; nullopt when neither works.
std::optional<std::vector<Vec3>> acrossWindowEdge(const RollingGrid& grid, const InflatedMap& inflated,
                                                  const Vec3& a, const Vec3& b) {
  if (auto through = gridPath(inflated, a, b, 3.0 * (b - a).norm() + 1.0, false, 1)) return through;
  auto inWindow = [&](const Vec3& p) { return grid.inWindow(grid.keyOf(p)); };
  if (inWindow(a) == inWindow(b)) return std::nullopt;
  // From the end inside (u) towards the one outside (v).
  const bool forward = inWindow(a);
  const Vec3 &u = forward ? a : b, &v = forward ? b : a;
  const double len = (v - u).norm();
  double s_edge = 0.0;
  for (double s = 0.0; s <= len; s += 0.5 * grid.resolution())
    if (inWindow(u + (v - u) * (s / len))) s_edge = s;
  const std::optional<Vec3> c = snapFree(inflated, u + (v - u) * (std::max(0.0, s_edge - 0.3) / len), 0.6);
  if (!c || castRay(inflated, *c, v, false).blocked) return std::nullopt;
  auto part = gridPath(inflated, u, *c, 3.0 * (*c - u).norm() + 1.0, false, 1);
  if (!part) return std::nullopt;
  part->push_back(v);
  if (!forward) std::reverse(part->begin(), part->end());
  return part;
}

std::optional<std::vector<Vec3>> planFrom(const ConnectivityGraph& g, const RollingGrid& grid,
                                          const InflatedMap& inflated, const Vec3& from, const Vec3& to,
                                          const FlightPathOptions& fo) {
  auto inWindow = [&](const Vec3& p) { return grid.inWindow(grid.keyOf(p)); };
  PathSearchOptions opt;
  opt.shortcut = false;
  // Remembered obstacles within the clearance of the start cannot be kept clear of: not avoided.
  for (const Vec3& s : fo.avoid)
    if ((s - from).norm() > fo.clearance) opt.avoid.push_back(s);
  opt.avoid_radius = fo.clearance;
  const GraphPath gp = g.size() > 0 ? findGraphPath(g, grid, from, to, opt) : GraphPath{};
  const bool dbg = std::getenv("USSNAV_DEBUG_PATH") != nullptr;
  if (!gp.found) {
    if (dbg) std::fprintf(stderr, "  path: no graph path to (%.2f %.2f %.2f) inwindow=%d\n", to.x(), to.y(), to.z(), int(inWindow(to)));
    if (!inWindow(to)) return std::nullopt;
    return gridPath(inflated, from, to, 3.0 * (to - from).norm() + 2.0, true, 1);
  }
  // Graph points into the flight band and out of the clearance margin (polyhedron centres may
  // lie closer to a wall than the clearance).
  std::vector<Vec3> clamped{gp.points.front()};
  for (size_t i = 1; i + 1 < gp.points.size(); ++i) {
    Vec3 q = gp.points[i];
    q.z() = std::clamp(q.z(), std::max(fo.waypoint_z_min, fo.z_min + grid.resolution()),
                       std::min(fo.waypoint_z_max, fo.z_max - grid.resolution()));
    if (auto s2 = snapFree(inflated, q, 0.6)) clamped.push_back(*s2);
  }
  clamped.push_back(gp.points.back());
  const std::vector<Vec3> pts = shortcutPolyline(inflated, clamped, true);
  std::vector<Vec3> out{pts.front()};
  for (size_t i = 1; i < pts.size(); ++i) {
    const Vec3 &a = pts[i - 1], &b = pts[i];
    if (castRay(inflated, a, b, false).blocked) {
      if (!inWindow(a) || !inWindow(b)) {
        // The segment crosses the window's edge (the route leaves the window, or comes back
        // into it after a stretch the window has forgotten).
        auto across = acrossWindowEdge(grid, inflated, a, b);
        if (!across) {
          if (dbg) std::fprintf(stderr, "  path: blocked segment (%.2f %.2f %.2f)-(%.2f %.2f %.2f) across the window's edge, no detour\n", a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
          return std::nullopt;
        }
        out.insert(out.end(), across->begin() + 1, across->end());
        continue;
      }
      // Inside the window the detour keeps to space the map has seen free: the unknown there is
      // what the sensors have not looked at yet (a chair seat in the LiDAR's blind cone, the
      // foot of a wall seen only from above), not free space.
      auto detour = gridPath(inflated, a, b, 3.0 * (b - a).norm() + 1.0, !fo.detour_through_unknown, 1);
      if (!detour) {
        if (dbg) std::fprintf(stderr, "  path: blocked segment (%.2f %.2f %.2f)-(%.2f %.2f %.2f) no detour\n", a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
        return std::nullopt;
      }
      out.insert(out.end(), detour->begin() + 1, detour->end());
      continue;
    }
    out.push_back(b);
  }
  // A window-edge detour or an attachment may still pass an obstacle remembered.
  if (polylinePassesNear(out, opt.avoid, fo.clearance)) {
    if (dbg) {
      std::fprintf(stderr, "  path from (%.2f %.2f %.2f): passes a remembered obstacle;", from.x(), from.y(), from.z());
      for (const Vec3& s : opt.avoid)
        if (polylinePassesNear(out, std::span<const Vec3>(&s, 1), fo.clearance))
          std::fprintf(stderr, " (%.2f %.2f %.2f) %.2f m from the start", s.x(), s.y(), s.z(), (s - from).norm());
      std::fprintf(stderr, "\n");
    }
    return std::nullopt;
  }
  return out;
}

}  // namespace

std::optional<std::vector<Vec3>> planFlightPath(const ConnectivityGraph& g, const RollingGrid& grid, const Vec3& from,
                                                const Vec3& to, const FlightPathOptions& opt) {
  const InflatedMap inflated(grid, opt.clearance, opt.z_min, opt.z_max);
  // A goal inside the clearance margin moves to the nearest point outside it.
  const std::optional<Vec3> goal = snapFree(inflated, to, 0.6);
  if (!goal) return std::nullopt;
  const Vec3& to2 = *goal;
  if (inflated.stateAt(from) != VoxelState::Occupied) return planFrom(g, grid, inflated, from, to2, opt);
  const std::optional<Vec3> e = escapePoint(grid, inflated, from, opt.body_radius);
  if (!e && std::getenv("USSNAV_DEBUG_PATH")) std::fprintf(stderr, "  path: no escape from (%.2f %.2f %.2f)\n", from.x(), from.y(), from.z());
  if (!e) return std::nullopt;
  auto rest = planFrom(g, grid, inflated, *e, to2, opt);
  if (!rest) return std::nullopt;
  rest->insert(rest->begin(), from);
  return rest;
}

std::optional<FlightPlan> planFlightPathLadder(const ConnectivityGraph& g, const RollingGrid& grid, const Vec3& from,
                                               const Vec3& to, const FlightPathOptions& opt,
                                               std::span<const double> clearances) {
  FlightPathOptions o = opt;
  for (const bool past : {false, true}) {
    if (past) {
      if (opt.avoid.empty()) break;
      o.avoid.clear();
      if (std::getenv("USSNAV_DEBUG_PATH")) std::fprintf(stderr, "  path: again, past the remembered obstacles\n");
    }
    for (const bool unknown : {false, true})
      for (const double c : clearances) {
        o.clearance = c;
        o.detour_through_unknown = unknown;
        if (auto p = planFlightPath(g, grid, from, to, o)) return FlightPlan{std::move(*p), c, unknown, past};
      }
  }
  return std::nullopt;
}

std::optional<Vec3> blockedAt(const OccupancyMap& map, const std::vector<Vec3>& path, double horizon) {
  double walked = 0.0;
  const size_t first = !path.empty() && map.stateAt(path[0]) == VoxelState::Occupied ? 2 : 1;
  for (size_t i = first; i < path.size() && walked < horizon; ++i) {
    if (const RayHit hit = castRay(map, path[i - 1], path[i], false); hit.blocked) return hit.point;
    walked += (path[i] - path[i - 1]).norm();
  }
  return std::nullopt;
}

FlightSettings flightSettings(const Config& cfg, double flight_z) {
  FlightSettings s;
  FlightPathOptions& o = s.options;
  const double radius = cfg.sim.uav.radius, clearance = cfg.episode.clearance;
  o.clearance = clearance;
  o.body_radius = radius + 0.02;
  o.z_min = std::max(radius + 0.25, flight_z - 0.7);
  o.z_max = flight_z + 0.8;
  o.waypoint_z_min = flight_z - 0.3;
  o.waypoint_z_max = flight_z + kApproachAbove;
  s.clearances = {clearance};
  for (const double margin : {0.1, 0.05})
    if (clearance > radius + margin) s.clearances.push_back(radius + margin);
  return s;
}

}  // namespace ussnav
