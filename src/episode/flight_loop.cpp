#include "flight_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ussnav/core/error.hpp"
#include "ussnav/episode/beyond_objects.hpp"
#include "ussnav/episode/episode_debug.hpp"
#include "ussnav/episode/episode_drawing.hpp"
#include "ussnav/eval/metrics.hpp"
#include "ussnav/eval/scene_quality.hpp"
#include "ussnav/mapping/map_drawing.hpp"
#include "ussnav/perception/oracle_detector.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"

namespace ussnav {

namespace {

// Free text -> target categories and an optional room; an instruction naming no object is an error.
Instruction objectInstruction(const std::string& text, const CommonsensePriors& priors) {
  Instruction in = interpretInstruction(text, priors);
  if (in.targets.empty())
    throw InputError("goal", "", "'" + text + "' names a room but no object; ussnav goto flies to rooms");
  return in;
}

GroundTruthGoal groundTruth(const Simulator& sim, const GoalMatcher& goal, const Pose& start, double found_radius,
                            const CommonsensePriors& priors, int goal_room) {
  std::function<bool(const std::string&)> in_room;
  if (goal_room >= 0) in_room = [&](const std::string& type) { return priors.roomIndex(type) == goal_room; };
  return evaluateGoal(sim, goal, start, found_radius, in_room);
}

MapperOptions mapperOptions(const EpisodeConfig& ep) {
  MapperOptions o;
  o.fuse_depth = ep.fuse_depth;
  return o;
}

}  // namespace

FlightLoop::FlightLoop(const EpisodeSpec& spec, const Config& cfg)
    : cfg_(cfg),
      ep_(cfg.episode),
      R_(run_.result),
      encoder_(makeTextEncoder(cfg.perception)),
      priors_(CommonsensePriors::load(CommonsensePriors::defaultDir(), encoder_)),
      instruction_(objectInstruction(spec.goal, *priors_)),
      goal_room_(instruction_.room.empty() ? -1 : priors_->roomIndex(instruction_.room)),
      sim_(spec.world, cfg, spec.seed),
      start_(spec.start ? *spec.start : sim_.startPose()),
      goal_(instructionGoal(instruction_, encoder_, ep_.goal_similarity)),
      truth_(groundTruth(sim_, goal_, start_, ep_.found_radius, *priors_, goal_room_)),
      mapper_(cfg, mapperOptions(ep_),
              std::make_unique<OracleDetector>(sim_.instanceLabels(), OracleRealism::fromConfig(cfg.perception),
                                               spec.seed)),
      frontiers_(cfg.exploration),
      flight_z_(start_.position.z()),
      camera_(cfg.exploration, flight_z_),
      uav_(cfg.sim.uav, start_),
      dt_(1.0 / cfg.sim.frame_rate_hz),
      flight_(flightSettings(cfg, flight_z_)),
      last_clearance_(flight_.options.clearance),
      path_clearance_(flight_.options.clearance),
      look_steps_(ep_.look_around ? 4 : 0),
      slice_at_(std::getenv("USSNAV_DEBUG_SLICE")),
      debug_(std::getenv("USSNAV_DEBUG_EPISODE") != nullptr) {
  if (ep_.look_around) look_spots_.push_back(start_.position);
  R_.world = spec.world_name;
  R_.goal = spec.goal;
  R_.planner = spec.planner;
  R_.seed = spec.seed;
  R_.goal_instances = int(truth_.instances.size());
  R_.shortest_path_m = truth_.shortest_path;
  R_.view_shortest_m = shortestToView(sim_, truth_, start_.position.head<2>(), cfg_.perception.max_range);
  R_.multi_room = truth_.multi_room;
  setupReasoning(spec);
}

void FlightLoop::setupReasoning(const EpisodeSpec& spec) {
  RegionChooser coarse = spec.coarse;
  if ((spec.planner == "full" && !coarse) || goal_room_ >= 0) {
    const std::string& name = cfg_.reasoning.reasoner;
    if (name == "oracle" || name == "oracle-labels") {
      oracle_ = std::make_shared<OracleReasoner>(
          sim_.world(), roomsOf(sim_.world(), truth_.instances), std::make_shared<BuiltinReasoner>(priors_),
          chanceRule(cfg_.reasoning),
          name == "oracle" ? OracleReasoner::Knows::GoalRooms : OracleReasoner::Knows::RoomTypes);
      reasoner_ = oracle_;
    } else {
      reasoner_ = makeReasoner(cfg_.reasoning, priors_);
    }
    labeler_ = std::make_unique<RegionLabeler>(reasoner_, cfg_.reasoning.label_min_interval_s,
                                               cfg_.reasoning.label_queue, reasoner_->name() == "llm");
    if (spec.planner == "full" && !coarse) {
      decider_ = std::make_unique<CoarseDecider>(reasoner_, priors_, instruction_, cfg_.reasoning);
      coarse = decider_->chooser();
    }
  }
  planner_ = makePlanner(spec.planner, coarse);
}

EpisodeRun FlightLoop::fly(const EpisodeProgress& progress) {
  while (true) {
    const SensedFrame f = sense();
    const Stopwatch plan_sw;
    // 1. A confirmed object of the goal category: approach it and declare.
    bool end = declare(f);
    // (episode.look_first: not while still turning at take-off; then the nearest goal object
    // seen all round, not the first one seen.)
    const bool looking = look_steps_ > 0 && ep_.look_first;
    if (!end && !looking) chooseObject();
    // 2. Otherwise look around at take-off, then explore.
    if (!end && !approaching_) lookAround();
    if (!end && looking && look_steps_ == 0) chooseObject();
    if (approaching_) look_steps_ = 0;
    if (!end && !approaching_ && look_steps_ == 0)
      end = explore();
    else if (approaching_ && !end)
      keepApproaching();
    times_.add("planning", plan_sw.ms());

    R_.time_s = t_;
    R_.path_length_m = uav_.distanceTravelled();
    R_.collisions = uav_.collisions();
    if (progress) progress(R_);
    if (end) break;
    if (t_ >= ep_.max_time_s) {
      R_.end_reason = "time_budget";
      break;
    }
    if (ep_.max_distance_m > 0 && uav_.distanceTravelled() >= ep_.max_distance_m) {
      R_.end_reason = "distance_budget";
      break;
    }
    const Pose before = uav_.pose();
    if (!uav_.step(sim_.groundTruth(), dt_)) {
      g_.active = false;  // collision: the UAV dropped its path
      if (debug_) printCollision(t_, before.position, approaching_, g_.path, mapper_.grid(), sim_.groundTruth());
      if (ep_.end_on_collision) {
        R_.end_reason = "collision";
        t_ += dt_;
        R_.collisions = uav_.collisions();
        break;
      }
    }
    t_ += dt_;
  }
  finish();
  return std::move(run_);
}

SensedFrame FlightLoop::sense() {
  SensedFrame f = sim_.sense(uav_.pose(), t_);
  const MapperFrameReport rep = mapper_.process(MapperFrame{f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t_});
  double frame_ms = rep.total_ms;
  if (mapper_.objects())  // where each goal object seen in this frame was seen from
    for (const MappedObject& o : mapper_.objects()->objects()) {
      if (o.last_seen != t_ || !goal_.matches(o.label)) continue;
      tries_.seenFrom(o.id, f.pose.position, o.centroid);
      if (R_.search_m < 0 && nearGoalInstance(truth_, o.centroid, kSightingRadius)) {  // evaluation only
        R_.sighted_s = t_;
        R_.search_m = uav_.distanceTravelled();
        R_.approach_shortest_m = shortestToSuccess(sim_, truth_, f.pose.position.head<2>());
      }
    }
  {
    const Stopwatch sw;
    frontiers_.update(mapper_.grid(), mapper_.coverage(), mapper_.anchorNode(f.pose.position), t_);
    const double ms = sw.ms();
    times_.add("frontiers", ms);
    frame_ms += ms;
  }
  {
    const Stopwatch sw;
    camera_.updateKnown(mapper_.grid());
    camera_.updateSeen(f.depth);
    const double ms = sw.ms();
    times_.add("camera_coverage", ms);
    frame_ms += ms;
  }
  if (slice_at_ && t_ >= std::atof(slice_at_)) {
    slice_at_ = nullptr;  // once, at the first frame at or after the time given
    std::fprintf(stderr, "[t=%.1f] band slice at flight height, UAV at (%.2f %.2f); F: frontier columns\n%s", t_,
                 uav_.pose().position.x(), uav_.pose().position.y(),
                 asciiSlice(mapper_.grid(), mapper_.coverage(), frontiers_.frontierCells(), flight_z_).c_str());
  }
  times_.add("frame_update", frame_ms);
  ++R_.frames;
  run_.trajectory.push_back({t_, uav_.pose()});
  if (t_ >= next_cov_) {
    R_.coverage.push_back({t_, camera_.knownArea(), camera_.seenKnownArea()});
    next_cov_ += 5.0;
  }
  return f;
}

std::optional<std::vector<Vec3>> FlightLoop::flightPath(const Vec3& a, const Vec3& b) {
  // The full clearance where a path keeps it; else UAV radius + 0.1 m (a point in a voxel is up
  // to 0.087 m from its centre) through space seen free; only when none does may a detour cross
  // voxels not seen yet.
  // Obstacles that blocked a path before and that the window has forgotten: kept clear of.
  FlightPathOptions opt = flight_.options;
  opt.avoid = blocked_.forgotten(mapper_.grid());
  auto plan = planFlightPathLadder(mapper_.graph(), mapper_.grid(), a, b, opt, flight_.clearances);
  if (!plan) return std::nullopt;
  last_clearance_ = plan->clearance;
  ++R_.paths_planned;
  if (plan->clearance < ep_.clearance) ++R_.paths_narrow;
  if (plan->through_unknown) ++R_.paths_through_unknown;
  if (plan->past_remembered) ++R_.paths_past_remembered;
  return std::move(plan->path);
}

int FlightLoop::rememberObstacle(const Vec3& hit, double margin) {
  return blocked_.addBlockedAt(mapper_.grid(), hit, margin);
}

void FlightLoop::refreshSemantics() {
  if (!labeler_ || semantics_t_ == t_) return;
  const Stopwatch sw;
  semantics_t_ = t_;
  snapshot_ = buildSceneGraph(mapper_, t_);
  summaries_ = summarizeRegions(snapshot_);
  labeler_->offer(summaries_, t_);
  if (oracle_) oracle_->setScene(summaries_);
  if (decider_) {
    auto scene = summaries_;
    if (cfg_.reasoning.beyond_via_frontier) {
      const int moved = facingFrontierRegions(scene, targets_, mapper_.grid());
      if (debug_ && moved > 0) std::fprintf(stderr, "[t=%.1f] %d objects seen beyond: to the region facing them\n", t_, moved);
    }
    decider_->setScene(std::move(scene), labeler_->semantics());
  }
  times_.add("semantics", sw.ms());
}

void FlightLoop::finish() {
  R_.time_s = t_;
  R_.path_length_m = uav_.distanceTravelled();
  R_.collisions = uav_.collisions();
  R_.remembered_obstacles = int(blocked_.size());
  R_.spl = R_.success && R_.shortest_path_m >= 0
               ? splOf(true, R_.path_length_m, std::max(R_.shortest_path_m, 1e-6))
               : 0.0;
  nlohmann::json stages = mapper_.times().summary();
  const nlohmann::json mine = times_.summary();
  for (auto it = mine.begin(); it != mine.end(); ++it) stages[it.key()] = it.value();
  R_.stage_ms = stages;
  const double med = times_.median("frame_update");
  R_.update_hz = med > 0 ? 1000.0 / med : 0.0;
  run_.graph = buildSceneGraph(mapper_, t_, R_.world);
  R_.reasoning = {{"instruction", instruction_.text}, {"targets", instruction_.targets},
                  {"room", instruction_.room}, {"interpreted", instruction_.how}};
  if (decider_) R_.reasoning.update(decider_->report());
  if (labeler_) {
    labeler_->offer(summarizeRegions(run_.graph), 1e18);  // label the final regions too
    labeler_->drain();
    const auto ls = labeler_->stats();
    R_.reasoning["reasoner"] = reasoner_->name();
    R_.reasoning["labels"] = {{"requests", ls.requests}, {"cache_hits", ls.cache_hits}, {"dropped", ls.dropped},
                              {"fallbacks", ls.fallbacks}, {"label_ms", latencySummary(ls.latency_ms)}};
    const auto sem = labeler_->semantics();
    for (SgRegion& r : run_.graph.regions)
      if (auto it = sem.find(r.id); it != sem.end()) r.label = it->second.label, r.description = it->second.description;
    const RegionLabelQuality lq =
        regionLabelQuality(run_.graph, sim_.world(), [&](const std::string& name) { return priors_->roomIndex(name); });
    R_.labels_scored = lq.scored;
    R_.labels_correct = lq.correct;
    R_.region_labels = {{"regions", lq.regions}, {"labelled", lq.labelled}, {"scored", lq.scored},
                        {"correct", lq.correct}, {"accuracy", lq.accuracy}, {"confusions", lq.confusions}};
  }
  R_.reasoner_fallbacks = decider_ ? decider_->stats().fallbacks : 0;
  {
    const RegionQuality rq = regionQuality(run_.graph, sim_.world());
    R_.region_count = rq.count;
    R_.region_largest_share = rq.largest_share;
    R_.region_ari = rq.nodes_scored > 1 ? rq.ari : -1.0;
    R_.regions = {{"count", rq.count}, {"largest_share", R_.region_largest_share}, {"nodes_in_rooms", rq.nodes_scored},
                  {"rooms_touched", rq.rooms_touched}};
    if (R_.region_ari > -1.0) R_.regions["purity"] = rq.purity, R_.regions["ari"] = rq.ari;
  }
  run_.topdown = drawEpisode(sim_.world(), run_, camera_, truth_.instances, start_);
  run_.overlay = worldOverlay(sim_.world(), truth_.instances);
  R_.wall_s = wall_.ms() / 1000.0;
}

EpisodeRun runEpisode(const EpisodeSpec& spec, const Config& cfg, const EpisodeProgress& progress) {
  FlightLoop loop(spec, cfg);
  return loop.fly(progress);
}

}  // namespace ussnav
