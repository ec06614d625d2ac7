#pragma once
// runEpisode's flight loop (episode.hpp) as a class: what one episode keeps from frame to frame,
// and one method per step of a frame. Internal to src/episode.
//
//   constructor       the instruction, the reasoner (full planner or a room constraint), the
//                     simulator and, for the evaluation only, the goal's ground truth
//   sense()           sensors -> Mapper (grid, coverage, graph, regions, objects) -> frontiers,
//                     camera coverage                                  (flight_loop.cpp)
//   declare()         at an approach pose: look, then declare the object found or give it up
//   chooseObject()    a confirmed goal object: fly to an approach pose, or in transit to a
//                     graph node near it                               (flight_loop_approach.cpp)
//   keepApproaching() keep an approach's path clear; choose again when it is blocked
//   lookAround()      three 120-degree turns at take-off (episode.look_around) and at reached
//                     viewpoints far from earlier turns (episode.look_again_m)
//   explore()         no object to approach: re-plan when needed (target, viewpoint, path),
//                     spin when nothing is left, give up          (flight_loop_explore.cpp)
//   finish()          metrics, stage times, the scene graph, region-label quality, the picture
//
// The pipeline's steps never read ground truth; only the constructor's GroundTruthGoal and
// finish() do, for the evaluation.

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ussnav/core/timing.hpp"
#include "ussnav/episode/approach.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/episode/episode_judge.hpp"
#include "ussnav/episode/flight_path.hpp"
#include "ussnav/episode/goal.hpp"
#include "ussnav/episode/search_memory.hpp"
#include "ussnav/eval/region_oracle.hpp"
#include "ussnav/exploration/camera_coverage.hpp"
#include "ussnav/exploration/frontier.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/reasoning/coarse_decider.hpp"
#include "ussnav/reasoning/instruction.hpp"
#include "ussnav/reasoning/region_labeler.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/uav.hpp"

namespace ussnav {

class FlightLoop {
 public:
  // Throws InputError for an instruction that names no object or an unknown planner.
  FlightLoop(const EpisodeSpec& spec, const Config& cfg);
  // Flies until the episode ends; `progress` is called every frame.
  EpisodeRun fly(const EpisodeProgress& progress);

 private:
  // The exploration target being flown to.
  struct Goal {
    bool active = false;
    TargetKind kind = TargetKind::Frontier;
    Vec3 centroid = Vec3::Zero();
    Viewpoint vp;
    std::vector<Vec2i> patch_cells;  // unseen targets
    std::vector<Vec3> path;
  };

  SensedFrame sense();
  bool declare(const SensedFrame& f);  // true: the episode ends
  void chooseObject();
  void lookAround();
  bool explore();  // true: nothing left to explore (end_reason "explored")
  void keepApproaching();
  void finish();

  void setupReasoning(const EpisodeSpec& spec);
  std::optional<std::vector<Vec3>> flightPath(const Vec3& a, const Vec3& b);
  int rememberObstacle(const Vec3& hit, double margin);  // a path blocked at `hit` (BlockingObstacles)
  void startApproach(int id, ApproachPose pose, const std::vector<Vec3>& path, bool is_transit);
  void stopApproach();
  bool isMisreading(const MappedObject& o);
  bool isSighting(int id) const;
  void failObject(int id);
  void refreshSemantics();
  bool inGoalRoom(const MappedObject& o);
  bool needReplan(const char*& why);
  bool replan(const char* why);  // true: nothing left to explore
  void faceViewpoint();

  const Stopwatch wall_;
  const Config& cfg_;
  const EpisodeConfig& ep_;
  EpisodeRun run_;
  EpisodeResult& R_;

  // The instruction (reasoning/) and the goal; the ground truth is for the evaluation only.
  std::shared_ptr<const TextEncoder> encoder_;
  std::shared_ptr<const CommonsensePriors> priors_;
  Instruction instruction_;
  int goal_room_ = -1;  // the instruction's room constraint, -1 without
  Simulator sim_;
  Pose start_;
  GoalMatcher goal_;
  GroundTruthGoal truth_;

  // The coarse level: `full` asks the reasoner which region to search; a room constraint asks
  // it for region labels.
  std::shared_ptr<Reasoner> reasoner_;
  std::shared_ptr<OracleReasoner> oracle_;  // evaluation only: an upper bound that reads ground truth
  std::unique_ptr<RegionLabeler> labeler_;
  std::unique_ptr<CoarseDecider> decider_;
  std::unique_ptr<ExplorationPlanner> planner_;

  Mapper mapper_;
  FrontierFinder frontiers_;
  const double flight_z_;
  CameraCoverage camera_;
  Uav uav_;
  StageTimes times_;
  const double dt_;
  // Margins of the flight-path ladder: the full clearance, then narrower ones (doors of real
  // buildings are 0.8-0.9 m wide); each through seen-free space, then again through unseen
  // voxels (planFlightPathLadder).
  const FlightSettings flight_;
  // The margin of the last path flightPath found, and of the path being flown: the blocked-path
  // checks use it, so a path planned through a narrow door is not dropped as blocked at once.
  double last_clearance_, path_clearance_;

  double t_ = 0.0;
  Goal g_;
  TargetMemory memory_;  // targets given up on (search_memory.hpp)
  ObjectTries tries_;    // goal objects tried
  BlockingObstacles blocked_;  // obstacles that blocked paths being flown
  std::vector<ExplorationTarget> targets_;
  double last_check_ = -1e9;  // the last re-plan or target check
  int spins_left_ = -1;       // -1: not spinning; else yaw steps left before giving up
  int look_steps_;            // turns on the spot still to command, + 1 (take-off, look_again_m)
  std::vector<Vec3> look_spots_;  // where the UAV turned round (episode.look_around, look_again_m)

  // Approaching a goal object: at an approach pose, or in transit to a graph node near it.
  bool approaching_ = false;
  bool transit_ = false;
  double last_transit_check_ = -1e9;
  int approach_object_ = -1;
  ApproachPose approach_;
  int look_frames_ = 0;  // frames looked from the approach pose
  static constexpr int kLookFrames = 5;  // frames at an approach pose for the detector to see a goal object

  // Region semantics from a scene-graph snapshot (only when a reasoner is in use).
  std::vector<RegionSummary> summaries_;
  SceneGraph snapshot_;
  double semantics_t_ = -1e9;

  double next_cov_ = 0.0;
  const char* slice_at_;        // USSNAV_DEBUG_SLICE: print the band once, at this time
  const bool debug_;            // USSNAV_DEBUG_EPISODE
  std::set<int> misread_reported_;  // debug output: objects reported as misreadings
};

}  // namespace ussnav
