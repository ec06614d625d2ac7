#pragma once
// One ObjectNav episode in the simulator (issue 7, DESIGN.md evaluation protocol): the flight
// loop. Each frame: sense -> Mapper (grid, coverage, graph, regions, objects) -> frontiers and
// camera coverage. When the object layer holds a confirmed object of the goal category, the UAV
// flies to a safe pose within found_radius of it, facing it, and declares "found"; the episode
// ends and the evaluation judges it against ground truth (a goal instance within found_radius
// and in view). Otherwise the planner picks a target (frontier or camera-unseen patch) and a
// viewpoint; the path comes from the connectivity graph (findGraphPath, shortcut by line of
// sight) and is re-checked against the grid every replan period; the kinematic UAV follows it.
// Re-plan when the viewpoint is reached, its target vanished, the path is blocked, or the
// period elapsed. Ends on found, on exhausted targets, or on the time / distance budget.
// The pipeline never reads ground truth; only the evaluation (success, L*, splits) does.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/core/config.hpp"
#include "ussnav/core/image.hpp"
#include "ussnav/exploration/planner.hpp"
#include "ussnav/scene_graph/scene_graph.hpp"
#include "ussnav/scene_graph/viewer.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

struct EpisodeSpec {
  World world;
  std::string world_name;          // for reports
  std::string goal;                // instruction in free text: "bed", "somewhere to sleep", ...
  std::string planner = "frontier";
  uint64_t seed = 1;
  std::optional<Pose> start;       // default: the world's start pose (moved to free space)
  RegionChooser coarse;            // optional coarse level for the `full` planner
};

struct FoundObject {
  int id = -1;
  std::string label;
  Vec3 position = Vec3::Zero();
};

struct CoverageSample {
  double t = 0.0;
  double known_m2 = 0.0;        // free area at flight height the map has known
  double camera_seen_m2 = 0.0;  // of that, what the camera has looked at
};

struct TrajectorySample {
  double t = 0.0;
  Pose pose;
};

struct EpisodeResult {
  std::string world, goal, planner;
  uint64_t seed = 1;
  bool success = false;
  double spl = 0.0;
  double path_length_m = 0.0;
  double shortest_path_m = -1.0;   // L*; -1 when no goal instance is reachable
  double time_s = 0.0;
  int frames = 0;
  int collisions = 0;
  std::optional<FoundObject> found_object;
  std::string end_reason;          // found | wrong_object | explored | time_budget | distance_budget
  int goal_instances = 0;          // ground truth
  bool multi_room = false;         // no goal instance in the start room
  int replans = 0, unreachable = 0;
  int close_looks = 0;  // frontiers reached but still open, tried again from nearer (episode.close_look)
  // Flight paths planned, and how many of them needed a margin narrower than episode.clearance
  // or (the last resort) a detour through voxels not seen yet (planFlightPathLadder).
  int paths_planned = 0, paths_narrow = 0, paths_through_unknown = 0;
  int paths_past_remembered = 0;  // found only with the remembered obstacles left out
  int remembered_obstacles = 0;  // occupied voxels kept because they blocked a path being flown (BlockingObstacles)
  double update_hz = 0.0;          // 1000 / median per-frame scene-graph update (ms)
  nlohmann::json stage_ms;         // {stage: {median, p95, count}}
  std::vector<CoverageSample> coverage;  // every 5 s
  nlohmann::json reasoning = nlohmann::json::object();  // instruction, reasoner decisions, faults
  int reasoner_fallbacks = 0;      // coarse decisions answered by global utility after a fault
  // Ground truth (evaluation only): the path split at the first frame in which the UAV saw an
  // object it took for the goal that is a goal instance (its centroid within kSightingRadius of
  // an instance's box): `search_m` flown until then, and L* from where it was then
  // (`approach_shortest_m`). -1 when that never happened (or no success pose is reachable).
  double sighted_s = -1.0, search_m = -1.0, approach_shortest_m = -1.0;
  // ... and the least search: L* from the start to a point that sees a goal instance within the
  // detector's range (shortestToView); -1 when none is reachable.
  double view_shortest_m = -1.0;
  // Ground truth (evaluation only): the final regions' labels against the rooms they cover
  // (regionLabelQuality); empty without a reasoner or a world with room types.
  nlohmann::json region_labels;
  int labels_scored = 0, labels_correct = 0;
  // The final regions against the world's rooms (regionQuality): how many, the share of the
  // graph's nodes the largest holds (1: one region for everything), purity and ARI over the nodes
  // that lie in a room; ARI -1 where none does (a world without rooms). Evaluation only.
  nlohmann::json regions;
  int region_count = 0;
  double region_largest_share = 0.0, region_ari = -1.0;
  double wall_s = 0.0;
};

struct EpisodeRun {
  EpisodeResult result;
  SceneGraph graph;
  std::vector<TrajectorySample> trajectory;
  Image topdown{1, 1};
  ViewerOverlay overlay;  // ground truth for DIR/scene_graph.html (rooms, walls, goal instances)
};

// Called every frame with the frame count, sim time and the result so far (for progress lines).
using EpisodeProgress = std::function<void(const EpisodeResult&)>;

// Throws InputError for an unknown planner or an empty goal. Deterministic for a seed.
EpisodeRun runEpisode(const EpisodeSpec& spec, const Config& cfg, const EpisodeProgress& progress = {});

nlohmann::json toJson(const EpisodeResult& r);
// Writes DIR/result.json, DIR/scene_graph.json, DIR/scene_graph.html (the graph in a web page
// with the trajectory, the ground truth of run.overlay and the result), DIR/trajectory.csv and
// DIR/topdown.png.
void writeEpisode(const std::string& dir, const EpisodeRun& run);

}  // namespace ussnav
