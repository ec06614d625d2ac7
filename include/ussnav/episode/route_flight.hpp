#pragma once
// Flying a route known in advance (`ussnav goto`): a saved scene graph gives the global route,
// its nodes' centres from the start to the goal, but its polyhedra reach the faces of walls and
// furniture, so the straight legs between them graze door jambs and table edges. The UAV flies
// it the way the flight loop flies (episode.hpp): it senses and maps as it goes (Mapper: grid
// and connectivity graph, no objects, no regions) and flies each leg with planFlightPathLadder
// on that live map, keeping episode.clearance from what it sees. A leg ends at the furthest
// point of the route (sampled every 0.25 m, at most 6 tried, furthest first) at most
// `lookahead_m` beyond the UAV's progress that a safe path reaches: a route point behind a door
// may still be unknown while the doorway is seen free. Progress is the route sample nearest the
// UAV within the lookahead. A leg is re-planned when flown (an intermediate one 1 m before its
// end) or when the map shows it blocked, not on a timer (a path starts at the live graph's node
// nearest the UAV, often behind it). Without a safe path the UAV hovers and looks along the
// route, then round, trying again every 0.5 s. The occupied voxels that blocked a leg are
// remembered (BlockingObstacles, search_memory.hpp): once the rolling window forgets them, later
// legs keep their clearance from them.
// The route's last point is walked back towards the one before it (0.2 m steps) until a safe
// path reaches it (a goal set beside an object's box may lie inside the clearance margin).
// Ends: arrived (within episode.goal_tolerance + 0.2 m of the last point reached), collision,
// no safe path for `stall_s`, or episode.max_time_s. Deterministic for a seed.

#include <string>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/sim/simulator.hpp"

namespace ussnav {

struct RouteFlightOptions {
  double lookahead_m = 4.0;   // a leg goes at most this far along the route
  double reach_m = 0.6;       // a leg shorter than this goes nowhere (the UAV is stalled)
  double stall_s = 10.0;      // give up after this long without a safe path
  double replan_period_s = -1.0;  // blocked-path check period; < 0: episode.replan_period_s
};

struct RouteFlight {
  bool arrived = false;
  std::string end_reason;     // arrived | collision | no_safe_path | time_budget
  double path_length_m = 0.0;
  double time_s = 0.0;
  int collisions = 0;
  int legs = 0;               // flight paths planned
  int narrow_legs = 0;        // of those, with a margin narrower than episode.clearance
  int blocked = 0;            // legs re-planned because the map showed them blocked
  int remembered_obstacles = 0;  // occupied voxels remembered at those blocks
  Vec3 end = Vec3::Zero();    // the route's last point as flown to (after walking it back)
  double end_shift_m = 0.0;   // how far it was walked back
  Pose final_pose;
};

// `route` from the start pose's position to the goal (at least one point), flown in `sim` (the
// caller's, which also gave the start pose). Throws InputError on an empty route.
RouteFlight flyRoute(Simulator& sim, const Config& cfg, const Pose& start, const std::vector<Vec3>& route,
                     const RouteFlightOptions& opt = {});

}  // namespace ussnav
