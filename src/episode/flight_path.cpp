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

std::optional<std::vector<Vec3>> planFrom(const ConnectivityGraph& g, const RollingGrid& grid,
                                          const InflatedMap& inflated, const Vec3& from, const Vec3& to,
                                          const FlightPathOptions& fo) {
  auto inWindow = [&](const Vec3& p) { return grid.inWindow(grid.keyOf(p)); };
  PathSearchOptions opt;
  opt.shortcut = false;
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
      if (!inWindow(a)) {
        if (dbg) std::fprintf(stderr, "  path: blocked segment starts outside the window\n");
        return std::nullopt;
      }
      if (!inWindow(b)) {
        // The map only knows the part inside the window: a voxel path that treats the space
        // beyond as passable (checked again when the window gets there) ...
        if (auto through = gridPath(inflated, a, b, 3.0 * (b - a).norm() + 1.0, false, 1)) {
          out.insert(out.end(), through->begin() + 1, through->end());
          continue;
        }
        // ... else a detour to where the segment leaves it (0.3 m inside), keeping the rest
        // when that does not cross what the window shows blocked either (the flight loop
        // would reject the path as soon as it is flown, and the same path would come back).
        const double len = (b - a).norm();
        double s_exit = 0.0;
        for (double s2 = 0.0; s2 <= len; s2 += 0.5 * grid.resolution())
          if (inWindow(a + (b - a) * (s2 / len))) s_exit = s2;
        const Vec3 c0 = a + (b - a) * (std::max(0.0, s_exit - 0.3) / len);
        const std::optional<Vec3> c = snapFree(inflated, c0, 0.6);
        std::optional<std::vector<Vec3>> part;
        if (c && !castRay(inflated, *c, b, false).blocked)
          part = gridPath(inflated, a, *c, 3.0 * (*c - a).norm() + 1.0, false, 1);
        if (!part) {
          if (dbg) std::fprintf(stderr, "  path: blocked segment leaving the window, no detour\n");
          return std::nullopt;
        }
        out.insert(out.end(), part->begin() + 1, part->end());
        out.push_back(b);
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
  for (const bool unknown : {false, true})
    for (const double c : clearances) {
      FlightPathOptions o = opt;
      o.clearance = c;
      o.detour_through_unknown = unknown;
      if (auto p = planFlightPath(g, grid, from, to, o)) return FlightPlan{std::move(*p), c, unknown};
    }
  return std::nullopt;
}

bool pathBlocked(const OccupancyMap& map, const std::vector<Vec3>& path, double horizon) {
  double walked = 0.0;
  const size_t first = !path.empty() && map.stateAt(path[0]) == VoxelState::Occupied ? 2 : 1;
  for (size_t i = first; i < path.size() && walked < horizon; ++i) {
    if (castRay(map, path[i - 1], path[i], false).blocked) return true;
    walked += (path[i] - path[i - 1]).norm();
  }
  return false;
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
