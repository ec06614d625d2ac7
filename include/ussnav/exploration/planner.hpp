#pragma once
// Exploration planners behind one interface (paper Sec. V-A/B and its baselines). Each re-plan
// the flight loop hands over the current targets — frontier clusters and camera-unseen patches,
// each with viewpoints — and the planner picks the target to fly to next:
//   frontier  the paper's baseline: global utility gain / cost over all targets, no regions;
//   tsp       FUEL-like: an open TSP tour from the UAV over every target's best viewpoint, first
//             stop of the tour;
//   full      coarse-to-fine: the coarse level picks a region (a RegionChooser: by default the
//             region holding the best target, kept while it still has targets); the fine level
//             flies to that region's best gain / cost target and orders the rest by an open tour
//             from it: episode.tour `search` (the default) minimises the gain-weighted arrival
//             times (solveSearchTour), `distance` is the plain TSP. (Flying to the tour's own
//             first stop was measured: it takes near slivers first, multi-room SPL 0.34 against
//             0.41 with the best target first.)
// Cost of a viewpoint = max(graph distance / max speed, yaw_weight * |yaw change| / yaw rate).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/exploration/viewpoint.hpp"
#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

enum class TargetKind { Frontier, Unseen };
const char* toString(TargetKind k);

// One place worth looking at.
struct ExplorationTarget {
  TargetKind kind = TargetKind::Frontier;
  int source_id = -1;                // frontier id, or unseen-patch index
  Vec3 centroid = Vec3::Zero();
  std::vector<Viewpoint> viewpoints; // best gain first, non-empty
  double gain = 0.0;                 // of the best viewpoint, in the planner's unit (see below)
  int region = -1;                   // region of the node nearest the best viewpoint, -1 none
};

// Gain units (set by the flight loop, src/episode/flight_loop.hpp): a visible frontier cell
// counts 1, plus exploration.unknown_volume_weight per m^3 of unknown space behind it; a
// camera-unseen cell 4.

struct PlanInput {
  const ConnectivityGraph* graph = nullptr;
  const OccupancyMap* map = nullptr;
  Pose uav;
  double time = 0.0;
  const std::vector<ExplorationTarget>* targets = nullptr;
  const UavConfig* uav_cfg = nullptr;
  const EpisodeConfig* episode_cfg = nullptr;
  std::function<int(int node)> region_of;  // node -> region, may be empty (no regions)
};

struct PlanChoice {
  int target = -1;           // index into *targets, -1: nothing to do
  int viewpoint = 0;         // index into that target's viewpoints
  int region = -1;           // region chosen by the coarse level (full), else the target's
  double cost_s = 0.0;       // estimated cost of reaching it, s
  std::vector<int> tour;     // targets in visiting order (tsp, full), first == target
  std::string note;          // one line: why
};

// Per-target travel cost from the UAV (seconds) and the node used; shared by the planners.
struct TargetCost {
  double cost_s = 0.0;       // best viewpoint
  int viewpoint = 0;
  int node = -1;
  double distance_m = 0.0;
};
std::vector<TargetCost> targetCosts(const PlanInput& in);

class ExplorationPlanner {
 public:
  virtual ~ExplorationPlanner() = default;
  virtual std::string name() const = 0;
  virtual PlanChoice choose(const PlanInput& in) = 0;
};

// Coarse level of `full`: returns the region to search among those holding targets
// (`candidates`, with the summed utility of each), or -1 to let the planner decide.
struct RegionCandidate {
  int region = -1;
  int targets = 0;
  double gain = 0.0;
  double cost_s = 0.0;       // cheapest target in it
  double best_utility = 0.0; // max over its targets of gain / cost (the frontier planner's criterion)
  double frontier_gain = 0.0;  // part of `gain` from frontier targets (the rest: unseen patches)
};
using RegionChooser = std::function<int(const PlanInput&, const std::vector<RegionCandidate>&)>;

// "frontier" | "tsp" | "full"; throws InputError (file "planner") for another name.
std::unique_ptr<ExplorationPlanner> makePlanner(const std::string& name, RegionChooser coarse = {});
const std::vector<std::string>& plannerNames();

}  // namespace ussnav
