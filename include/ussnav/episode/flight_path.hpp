#pragma once
// The path the UAV flies to a goal (issue 7, flight loop): A* on the connectivity graph
// (findGraphPath, edges re-checked against the grid), then line-of-sight shortcutting in the
// grid inflated by the UAV's clearance, then every segment that still comes closer than the
// clearance to a known obstacle is replaced by a voxel A* path in the inflated grid through
// voxels seen free (one that crosses the window's edge, leaving it or coming back into it,
// may cross the unknown space beyond it, re-checked when the window gets there; inside the
// window unknown is what the sensors have not looked at, such as the foot of a wall in the
// LiDAR's blind cone, and is not flown through unless detour_through_unknown). When the graph
// has no path and the goal lies in the window, a voxel A* through known free, inflated space is
// the fallback. When the UAV itself stands inside the clearance margin (the map grew an
// obstacle next to it), the path first steps straight to the nearest voxel with full clearance
// within 0.8 m that it can reach keeping `body_radius` from every mapped obstacle. nullopt when no safe path is found: a segment is never returned that
// the inflated map shows blocked. Paths stay in the band [z_min, z_max] (voxels outside it
// count as obstacles; graph points are clamped into a narrower band around flight height,
// where doors and furniture leave the most room).

#include <optional>
#include <span>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

struct FlightPathOptions {
  double clearance = 0.4;     // from mapped obstacles, m
  double body_radius = 0.27;  // the escape step keeps at least this, m
  double z_min = 0.5, z_max = 2.0;  // flight band: voxels outside it count as obstacles
  double waypoint_z_min = 0.9, waypoint_z_max = 1.5;  // graph points are clamped into this band
  // Detours inside the window may cross unknown voxels: a last resort for the caller when no
  // path keeps to seen-free space (the UAV boxed in by what its sensors have not seen yet).
  bool detour_through_unknown = false;
  // Obstacles the map no longer holds (beyond the window) that blocked a path before
  // (BlockingObstacles): no graph edge and no segment of the path comes within `clearance` of
  // them (those already within it of the start excepted).
  std::vector<Vec3> avoid;
};

std::optional<std::vector<Vec3>> planFlightPath(const ConnectivityGraph& g, const RollingGrid& grid, const Vec3& from,
                                                const Vec3& to, const FlightPathOptions& opt);

// A path and how it was found.
struct FlightPlan {
  std::vector<Vec3> path;
  double clearance = 0.0;         // the margin it keeps from mapped obstacles, m
  bool through_unknown = false;   // a detour inside the window crosses voxels not seen yet
  bool past_remembered = false;   // found only with the remembered obstacles left out
};

// The flight loop's attempts, in order: planFlightPath at each of `clearances` (widest first:
// doors of real buildings are 0.8-0.9 m wide) keeping detours to space seen free; then, as the
// last resort, the same clearances again with detours through unseen voxels (opt's own
// clearance and detour_through_unknown are overridden). Both rounds go to the narrowest margin:
// beyond a narrow door that the rolling window has forgotten, only the narrowest margin passes
// the door and only unseen voxels lead on. When every attempt fails and opt.avoid is not empty,
// the whole ladder once more without it: remembered obstacles are kept clear of where a path
// can be, and left to the map where none can (a door whose jamb blocked a path once, and the
// only way back, would otherwise shut the UAV in). nullopt when every attempt fails.
std::optional<FlightPlan> planFlightPathLadder(const ConnectivityGraph& g, const RollingGrid& grid, const Vec3& from,
                                               const Vec3& to, const FlightPathOptions& opt,
                                               std::span<const double> clearances);

// The flight loop's settings for a UAV flying at `flight_z` (src/episode/flight_loop.hpp,
// route_flight.cpp): episode.clearance, the UAV's body radius + 0.02 m, the band
// flight_z - 0.7 .. + 0.8 m (never below radius + 0.25 m), graph points at
// flight_z - 0.3 .. + kApproachAbove, and the margin ladder episode.clearance, then
// radius + 0.1 m and radius + 0.05 m where narrower (a point in a voxel is up to 0.087 m from
// its centre).
// Whether the first `horizon` metres of a polyline cross an obstacle of `map` (pass an
// InflatedMap for a margin). When the polyline starts inside an obstacle (the UAV inside the
// margin), the first segment is the escape step out of it and is not judged. blockedAt gives
// where the first blocked segment meets the obstacle.
std::optional<Vec3> blockedAt(const OccupancyMap& map, const std::vector<Vec3>& path, double horizon);
inline bool pathBlocked(const OccupancyMap& map, const std::vector<Vec3>& path, double horizon) {
  return blockedAt(map, path, horizon).has_value();
}

struct FlightSettings {
  FlightPathOptions options;
  std::vector<double> clearances;
};
FlightSettings flightSettings(const Config& cfg, double flight_z);

}  // namespace ussnav
