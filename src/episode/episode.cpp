#include "ussnav/episode/episode.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/episode/approach.hpp"
#include "ussnav/episode/episode_debug.hpp"
#include "ussnav/episode/episode_drawing.hpp"
#include "ussnav/episode/episode_judge.hpp"
#include "ussnav/episode/exploration_targets.hpp"
#include "ussnav/episode/flight_path.hpp"
#include "ussnav/episode/goal.hpp"
#include "ussnav/episode/search_memory.hpp"
#include "ussnav/eval/metrics.hpp"
#include "ussnav/eval/region_oracle.hpp"
#include "ussnav/eval/scene_quality.hpp"
#include "ussnav/exploration/camera_coverage.hpp"
#include "ussnav/exploration/frontier.hpp"
#include "ussnav/exploration/graph_costs.hpp"
#include "ussnav/mapping/inflated_map.hpp"
#include "ussnav/mapping/map_drawing.hpp"
#include "ussnav/perception/oracle_detector.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/coarse_decider.hpp"
#include "ussnav/reasoning/instruction.hpp"
#include "ussnav/reasoning/region_labeler.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/uav.hpp"
#include "ussnav/skeleton/graph_search.hpp"

namespace ussnav {

namespace {

struct Goal {
  bool active = false;
  TargetKind kind = TargetKind::Frontier;
  Vec3 centroid = Vec3::Zero();
  Viewpoint vp;
  std::vector<Vec2i> patch_cells;  // unseen targets
  std::vector<Vec3> path;
};

}  // namespace

EpisodeRun runEpisode(const EpisodeSpec& spec, const Config& cfg, const EpisodeProgress& progress) {
  const Stopwatch wall;
  const EpisodeConfig& ep = cfg.episode;
  EpisodeRun run;
  EpisodeResult& R = run.result;
  R.world = spec.world_name;
  R.goal = spec.goal;
  R.planner = spec.planner;
  R.seed = spec.seed;

  // The instruction and the coarse level (reasoning/): free text -> target categories and an
  // optional room; the `full` planner asks the configured reasoner which region to search.
  const std::shared_ptr<const TextEncoder> encoder(makeTextEncoder(cfg.perception));
  const auto priors = CommonsensePriors::load(CommonsensePriors::defaultDir(), encoder);
  const Instruction instruction = interpretInstruction(spec.goal, *priors);
  if (instruction.targets.empty())
    throw InputError("goal", "", "'" + spec.goal + "' names a room but no object; ussnav goto flies to rooms");
  const int goal_room = instruction.room.empty() ? -1 : priors->roomIndex(instruction.room);
  Simulator sim(spec.world, cfg, spec.seed);
  const Pose start = spec.start ? *spec.start : sim.startPose();
  const GoalMatcher goal(spec.goal, instruction.targets, encoder, ep.goal_similarity);
  std::function<bool(const std::string&)> gt_in_room;
  if (goal_room >= 0) gt_in_room = [&](const std::string& type) { return priors->roomIndex(type) == goal_room; };
  const GroundTruthGoal truth = evaluateGoal(sim, goal, start, ep.found_radius, gt_in_room);
  R.goal_instances = int(truth.instances.size());
  R.shortest_path_m = truth.shortest_path;
  R.multi_room = truth.multi_room;

  std::shared_ptr<Reasoner> reasoner;
  std::shared_ptr<OracleReasoner> oracle;  // evaluation only: an upper bound that reads ground truth
  std::unique_ptr<RegionLabeler> labeler;
  std::unique_ptr<CoarseDecider> decider;
  RegionChooser coarse = spec.coarse;
  if ((spec.planner == "full" && !coarse) || goal_room >= 0) {
    if (cfg.reasoning.reasoner == "oracle" || cfg.reasoning.reasoner == "oracle-labels") {
      oracle = std::make_shared<OracleReasoner>(
          sim.world(), roomsOf(sim.world(), truth.instances), std::make_shared<BuiltinReasoner>(priors),
          cfg.reasoning.min_chance_ratio,
          cfg.reasoning.reasoner == "oracle" ? OracleReasoner::Knows::GoalRooms : OracleReasoner::Knows::RoomTypes);
      reasoner = oracle;
    } else {
      reasoner = makeReasoner(cfg.reasoning, priors);
    }
    labeler = std::make_unique<RegionLabeler>(reasoner, cfg.reasoning.label_min_interval_s, cfg.reasoning.label_queue,
                                              reasoner->name() == "llm");
    if (spec.planner == "full" && !coarse) {
      decider = std::make_unique<CoarseDecider>(reasoner, priors, instruction, cfg.reasoning);
      coarse = decider->chooser();
    }
  }
  std::unique_ptr<ExplorationPlanner> planner = makePlanner(spec.planner, coarse);

  auto detector = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), spec.seed);
  MapperOptions mopt;
  mopt.fuse_depth = ep.fuse_depth;
  Mapper mapper(cfg, mopt, std::move(detector));
  FrontierFinder frontiers(cfg.exploration);
  const double flight_z = start.position.z();
  CameraCoverage camera(cfg.exploration, flight_z);
  Uav uav(cfg.sim.uav, start);
  StageTimes times;
  const double dt = 1.0 / cfg.sim.frame_rate_hz;
  // Flight paths keep ep.clearance from mapped obstacles, or the UAV radius + 0.1 m (a point in a
  // voxel is up to 0.087 m from its centre) where no path keeps that much (narrow doors), through
  // space seen free; only when none does may a detour cross voxels not seen yet.
  // Margins of the flight-path ladder: the full clearance, then narrower ones (doors of real
  // buildings are 0.8-0.9 m wide); each through seen-free space, then again through unseen voxels.
  const FlightSettings flight = flightSettings(cfg, flight_z);
  const FlightPathOptions& fopt = flight.options;
  const std::vector<double>& clearances = flight.clearances;
  // The margin of the last path flightPath found, and of the path being flown: the blocked-path
  // checks use it, so a path planned through a narrow door is not dropped as blocked at once.
  double last_clearance = fopt.clearance, path_clearance = fopt.clearance;
  auto flightPath = [&](const Vec3& a, const Vec3& b) -> std::optional<std::vector<Vec3>> {
    auto plan = planFlightPathLadder(mapper.graph(), mapper.grid(), a, b, fopt, clearances);
    if (!plan) return std::nullopt;
    last_clearance = plan->clearance;
    ++R.paths_planned;
    if (plan->clearance < ep.clearance) ++R.paths_narrow;
    if (plan->through_unknown) ++R.paths_through_unknown;
    return std::move(plan->path);
  };

  Goal g;
  TargetMemory memory;  // targets given up on (search_memory.hpp)
  ObjectTries tries;    // goal objects tried
  std::set<int> misread_reported;         // debug output: objects reported as misreadings
  // A few frames misreading another object (a bed called "sofa") are no find: `o` is outvoted by
  // an object that is not the goal. Asked when an object is chosen and again when it is reached.
  auto isMisreading = [&](const MappedObject& o, double now) {
    const MappedObject* by = outvotedBy(*mapper.objects(), o);
    if (!by || goal.matches(by->label)) return false;
    if (std::getenv("USSNAV_DEBUG_EPISODE") && misread_reported.insert(o.id).second)
      std::fprintf(stderr, "[t=%.1f] object %d (%s, %d observations) skipped: a misreading of object %d (%s, %d)\n", now,
                   o.id, o.label.c_str(), o.n_observations, by->id, by->label.c_str(), by->n_observations);
    return true;
  };
  constexpr int kLookFrames = 5;  // frames at an approach pose for the detector to see a goal object
  int look_frames = 0;
  bool approaching = false;
  bool transit = false;  // approaching a graph node near the object, not the object itself
  double last_transit_check = -1e9;
  int approach_object = -1;
  ApproachPose approach;
  double last_check = -1e9;
  int spins_left = -1;  // -1: not spinning; else yaw steps left before giving up
  // episode.look_around: turns at take-off still to command, and one more step to finish the last.
  int look_steps = ep.look_around ? 4 : 0;
  const char* slice_at = std::getenv("USSNAV_DEBUG_SLICE");  // print the band once, at this time
  double t = 0.0;
  // A sighting, an object seen fewer than target_min_observations times, is approached once; a
  // failed approach to it counts no failure (its box, from a glimpse, may be off).
  auto isSighting = [&](int id) {
    const MappedObject* o = mapper.objects() ? mapper.objects()->find(id) : nullptr;
    return o && o->n_observations < ep.target_min_observations;
  };
  auto failObject = [&](int id) { tries.fail(id, t, ep.blacklist_s, isSighting(id)); };
  double next_cov = 0.0;
  std::vector<ExplorationTarget> targets;

  auto sample = [&] { run.trajectory.push_back({t, uav.pose()}); };

  // Region semantics from a scene-graph snapshot (only when a reasoner is in use).
  std::vector<RegionSummary> summaries;
  SceneGraph snapshot;
  double semantics_t = -1e9;
  auto refreshSemantics = [&] {
    if (!labeler || semantics_t == t) return;
    const Stopwatch sw;
    semantics_t = t;
    snapshot = buildSceneGraph(mapper, t);
    summaries = summarizeRegions(snapshot);
    labeler->offer(summaries, t);
    if (oracle) oracle->setScene(summaries);
    if (decider) decider->setScene(summaries, labeler->semantics());
    times.add("semantics", sw.ms());
  };
  // Room constraint: the reasoner's label of the region holding the object must name the room.
  auto inGoalRoom = [&](const MappedObject& o) {
    if (goal_room < 0) return true;
    refreshSemantics();
    const auto sem = labeler->semantics();
    const auto it = sem.find(o.region_id >= 0 ? o.region_id : regionAt(snapshot, o.centroid));
    return it != sem.end() && priors->roomIndex(it->second.label) == goal_room;
  };

  while (true) {
    SensedFrame f = sim.sense(uav.pose(), t);
    const MapperFrameReport rep = mapper.process(MapperFrame{f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
    double frame_ms = rep.total_ms;
    {
      const Stopwatch sw;
      frontiers.update(mapper.grid(), mapper.coverage(), mapper.anchorNode(f.pose.position), t);
      const double ms = sw.ms();
      times.add("frontiers", ms);
      frame_ms += ms;
    }
    {
      const Stopwatch sw;
      camera.updateKnown(mapper.grid());
      camera.updateSeen(f.depth);
      const double ms = sw.ms();
      times.add("camera_coverage", ms);
      frame_ms += ms;
    }
    if (slice_at && t >= std::atof(slice_at)) {
      slice_at = nullptr;  // once, at the first frame at or after the time given
      std::fprintf(stderr, "[t=%.1f] band slice at flight height, UAV at (%.2f %.2f); F: frontier columns\n%s", t,
                   uav.pose().position.x(), uav.pose().position.y(),
                   asciiSlice(mapper.grid(), mapper.coverage(), frontiers.frontierCells(), flight_z).c_str());
    }
    times.add("frame_update", frame_ms);
    ++R.frames;
    sample();
    if (t >= next_cov) {
      R.coverage.push_back({t, camera.knownArea(), camera.seenKnownArea()});
      next_cov += 5.0;
    }

    // --- Decide -------------------------------------------------------------------------
    const Stopwatch plan_sw;
    const RollingGrid& grid = mapper.grid();
    const ConnectivityGraph& graph = mapper.graph();
    bool end = false;

    // 1. A confirmed object of the goal category: approach it and declare.
    if (approaching && transit && uav.idle() && (uav.pose().position - approach.position).norm() <= ep.goal_tolerance) {
      approaching = transit = false;  // near the object now: look for an approach pose again below
      uav.setPath({});
    }
    if (approaching && uav.idle() && (uav.pose().position - approach.position).norm() <= ep.goal_tolerance) {
      const MappedObject* o = mapper.objects()->find(approach_object);
      // The evidence may have changed on the way: a "sofa" chosen while the bed under it had been
      // seen only a few times is, once the bed's views add up, a misreading. Then no
      // declaration: the choice below skips it and the exploration goes on.
      // And the UAV must see a goal object from here itself: a pose chosen near the object's box
      // may have a wall between the two that the map had not seen when the pose was chosen
      // (office-14 "toilet": the pose in the corridor, the toilet 0.8 m away behind the
      // bathroom wall). The detector misses an object in some frames, so it has kLookFrames
      // frames at the pose; seeing none, this approach failed, as one with no path does. An
      // object approached on a sighting of fewer than target_min_observations frames (below) is
      // declared only once its views here add up to that many.
      const MappedObject* seen =
          o ? seenWithin(*mapper.objects(), [&](const std::string& l) { return goal.matches(l); }, uav.pose().position,
                         ep.found_radius, t)
            : nullptr;
      const bool in_view = seen && inGoalRoom(*seen) && seen->n_observations >= ep.target_min_observations;
      if (o && isMisreading(*o, t)) {
        approaching = transit = false;
        uav.setPath({});
      } else if (!in_view && ++look_frames < kLookFrames) {
        // hover and look again
      } else if (!in_view) {
        if (std::getenv("USSNAV_DEBUG_EPISODE"))
          std::fprintf(stderr, "[t=%.1f] object %d reached, but no goal object in view from (%.2f %.2f %.2f) in %d frames\n", t,
                       approach_object, uav.pose().position.x(), uav.pose().position.y(), uav.pose().position.z(),
                       kLookFrames);
        tries.noViewFrom(approach_object, uav.pose().position);
        failObject(approach_object);
        approaching = transit = false;
        uav.setPath({});
      } else {
        R.found_object = FoundObject{approach_object, o ? o->label : "", o ? o->centroid : Vec3::Zero()};
        R.success = judgeFound(truth, uav.pose(), f.depth, ep.found_radius, cfg.perception.min_pixels);
        R.end_reason = R.success ? "found" : "wrong_object";
        end = true;
      }
    }
    // In transit, the object's own approach is tried again every replan period on the way.
    const bool retry_transit = approaching && transit && t - last_transit_check >= ep.replan_period_s;
    if (!end && (!approaching || retry_transit) && mapper.objects() && graph.size() > 0) {
      if (retry_transit) last_transit_check = t;
      const MappedObject* best = nullptr;
      double best_d = 1e18;
      for (const MappedObject& o : mapper.objects()->objects()) {
        // A confirmed object seen fewer than target_min_observations times is a sighting (a fridge
        // glimpsed through a door in two frames while flying past): it is approached as well, to
        // be looked at, and declared only when seen often enough from the pose (above); once (a
        // box from a glimpse may be off: house_18 "fridge", a pose that could not see it). Left
        // alone, it was seen again only when the exploration came back (office-4 "fridge": two
        // frames at 7 s, the third at 99 s).
        if (!o.confirmed || !goal.matches(o.label)) continue;
        if (o.n_observations < ep.target_min_observations && tries.sightingChecked(o.id)) continue;
        if (retry_transit && mapper.objects()->find(approach_object) != &o) continue;
        if (tries.skipped(o.id, t)) continue;
        if (!inGoalRoom(o)) continue;
        if (isMisreading(o, t)) continue;
        const double d = (o.centroid - uav.pose().position).norm();
        if (d < best_d) best_d = d, best = &o;
      }
      // Fly `path` to `pose` (the path's end is where the UAV will really stop).
      auto startApproach = [&](int id, ApproachPose pose, const std::vector<Vec3>& path, bool is_transit) {
        approaching = true, transit = is_transit, approach_object = id, approach = pose;
        look_frames = 0;
        approach.position = path.back();
        g = Goal{};
        g.active = true;
        g.path = path;
        uav.setPath(path);
        path_clearance = last_clearance;
      };
      if (best) {
        const GraphDistances gd(graph, grid, uav.pose().position);
        bool ok = false;
        for (const ApproachPose& ap : approachPoses(grid, gd, best->box, flight_z, cfg)) {
          if (tries.lookedInVainFrom(best->id, ap.position)) continue;  // (house_18 "fridge": twice)
          const auto p = flightPath(uav.pose().position, ap.position);
          if (!p) continue;
          startApproach(best->id, ap, *p, false);
          ok = true;
          break;
        }
        if (!ok && retry_transit) ok = true;  // keep flying the transit
        if (!ok && tries.mayTransit(best->id)) {
          // No pose the map can vouch for yet (the object was seen from afar, beyond the window or
          // through a door): fly to the graph node nearest to it, from where the window covers it.
          const int n = transitNode(graph, grid, best->box, best->centroid, flight_z, ep.transit_radius,
                                    tries.noPoseSpots(best->id));
          const Vec3 via = n >= 0 ? Vec3(graph.node(n).center.x(), graph.node(n).center.y(), flight_z) : Vec3::Zero();
          if (n >= 0 && (via - best->centroid).norm() <= ep.transit_radius &&
              (via - uav.pose().position).norm() > ep.goal_tolerance) {
            if (const auto p = flightPath(uav.pose().position, via)) {
              tries.countTransit(best->id);
              if (std::getenv("USSNAV_DEBUG_EPISODE"))
                std::fprintf(stderr, "[t=%.1f] object %d: transit to node %d (%.2f %.2f), %zu points\n", t, best->id, n,
                             via.x(), via.y(), p->size());
              last_transit_check = t;
              startApproach(best->id,
                            ApproachPose{via, std::atan2(best->centroid.y() - via.y(), best->centroid.x() - via.x()), 0.0},
                            *p, true);
              ok = true;
            }
          }
        }
        if (!ok) {
          // No pose from afar is no verdict on the object: the map around it is what is missing
          // (seen through a door; the transits cut short by a blocked path). It is tried again
          // later with one more transit, and only failures within transit_radius of it count
          // towards dropping it for good (a toilet missed this way ended an episode "explored").
          const bool near = (best->centroid - uav.pose().position).head<2>().norm() <= ep.transit_radius;
          // No place to look from here (house_6 "toilet": the node nearest to it is behind the
          // wall it stands against, and three transits there dropped it): the next one goes elsewhere.
          if (near) tries.noPoseFrom(best->id, uav.pose().position);
          tries.failFromAfar(best->id, t, ep.blacklist_s, near, isSighting(best->id));
          if (std::getenv("USSNAV_DEBUG_EPISODE"))
            std::fprintf(stderr, "[t=%.1f] object %d (%s) at (%.2f %.2f %.2f): no approach (%zu poses, uav %.2f %.2f%s)\n", t,
                         best->id, best->label.c_str(), best->centroid.x(), best->centroid.y(), best->centroid.z(),
                         approachPoses(grid, gd, best->box, flight_z, cfg).size(), uav.pose().position.x(),
                         uav.pose().position.y(), near ? ", near" : "");
          ++R.unreachable;
        }
      }
    }

    // Look around at take-off: three 120-degree turns on the spot, the goal approached as soon as
    // it is seen (1. above), then the first plan.
    if (!end && !approaching && look_steps > 0 && uav.idle()) {
      if (--look_steps > 0) {
        uav.setPath({});
        uav.setYawTarget(wrapAngle(uav.pose().yaw + 2.0 * kPi / 3.0));
      }
    }
    if (approaching) look_steps = 0;

    // 2. Otherwise explore.
    if (!end && !approaching && look_steps == 0) {
      bool need = !g.active || uav.pathDone();
      const char* why = !g.active ? "no target" : "path done";  // debug output only
      if (g.active && uav.pathDone()) {
        const double dyaw = std::abs(wrapAngle(g.vp.yaw - uav.pose().yaw));
        need = dyaw < 0.05 || (uav.pose().position - g.vp.position).norm() > ep.goal_tolerance;  // turned, or dropped
        if (need && (uav.pose().position - g.vp.position).norm() <= ep.goal_tolerance) {
          // Reached the viewpoint: whatever is left of its target is not visible from here.
          if (g.kind == TargetKind::Unseen) camera.abandon(g.patch_cells);
          const bool second = ep.close_look && g.kind == TargetKind::Frontier && !memory.lookedFrom(g.centroid);
          if (second) {
            memory.addLooked(g.centroid, uav.pose().position);
            ++R.close_looks;
          } else {
            memory.skipForGood(g.centroid);
          }
          if (std::getenv("USSNAV_DEBUG_EPISODE"))
            std::fprintf(stderr, "[t=%.1f] reached but %s target still open (%.2f %.2f %.2f)%s\n", t, toString(g.kind),
                         g.centroid.x(), g.centroid.y(), g.centroid.z(), second ? ": a closer look next" : "");
        }
      }
      if (g.active && !need && t - last_check >= ep.replan_period_s) {
        last_check = t;
        // Target still there? Path still clear?
        bool alive = false;
        if (g.kind == TargetKind::Frontier) {
          for (const Frontier& fr : frontiers.frontiers())
            if ((fr.centroid - g.centroid).norm() < 1.0) alive = true;
        } else {
          int unseen = 0;
          for (const Vec2i& c : g.patch_cells) unseen += !camera.isSeen(c);
          alive = unseen >= std::max(1, cfg.exploration.unseen_min_cells / 2);
        }
        if (!alive) need = true, why = "target gone or moved";
      }
      if (g.active && !need && !uav.pathDone()) {
        // Every frame: the next metres of the path against what the map knows now.
        const InflatedMap inflated(grid, std::min(cfg.sim.uav.radius + 0.1, path_clearance));
        if (pathBlocked(inflated, uav.remainingPath(), 4.0)) need = true, why = "path blocked";
      }
      if (need && spins_left > 0 && !uav.idle()) need = false;  // finish the current spin step
      if (need) {
        last_check = t;
        const std::vector<UnseenPatch> patches = camera.patches();
        targets = collectTargets(frontiers, patches, memory, t, graph, grid, cfg.exploration, ep.close_look, flight_z,
                                 std::getenv("USSNAV_DEBUG_EPISODE") != nullptr);
        if (std::getenv("USSNAV_DEBUG_EPISODE"))
          std::fprintf(stderr, "[t=%.1f] replan (%s): frontiers %zu (cells %zu) patches %zu targets %zu blacklist %zu spins %d\n", t,
                       why, frontiers.frontiers().size(), frontiers.cellCount(), patches.size(), targets.size(), memory.size(), spins_left);
        for (ExplorationTarget& tg : targets) {
          const int node = mapper.anchorNode(tg.viewpoints.front().position);
          tg.region = node >= 0 ? mapper.regions().regionOf(node) : -1;
        }
        if (decider) refreshSemantics();
        g.active = false;
        uav.setPath({});  // hover unless a new path is found below
        while (!targets.empty() && graph.size() > 0) {
          PlanInput in;
          in.graph = &graph;
          in.map = &grid;
          in.uav = uav.pose();
          in.time = t;
          in.targets = &targets;
          in.uav_cfg = &cfg.sim.uav;
          in.episode_cfg = &ep;
          in.region_of = [&](int node) { return mapper.regions().regionOf(node); };
          const PlanChoice choice = planner->choose(in);
          if (choice.target < 0) break;
          ++R.replans;
          const ExplorationTarget& tg = targets[size_t(choice.target)];
          const Viewpoint& vp = tg.viewpoints[size_t(choice.viewpoint)];
          const auto p = flightPath(uav.pose().position, vp.position);
          if (p && std::getenv("USSNAV_DEBUG_EPISODE")) printPlan(tg, vp, *p, choice, decider.get(), targets);
          if (p) {
            g.active = true;
            g.kind = tg.kind;
            g.centroid = tg.centroid;
            g.vp = vp;
            g.vp.position = p->back();  // the goal may have moved out of the clearance margin
            g.path = *p;
            g.patch_cells.clear();
            if (tg.kind == TargetKind::Unseen) g.patch_cells = patches[size_t(tg.source_id)].cells;
            uav.setPath(*p);
            path_clearance = last_clearance;
            spins_left = -1;
            break;
          }
          ++R.unreachable;
          const int times = memory.skipUnreachable(tg.centroid, t, ep.blacklist_s);
          if (std::getenv("USSNAV_DEBUG_EPISODE"))
            std::fprintf(stderr, "[t=%.1f] unreachable (%.2f %.2f %.2f) x%d\n", t, tg.centroid.x(), tg.centroid.y(),
                         tg.centroid.z(), times + 1);
          targets.erase(targets.begin() + choice.target);
        }
        if (!g.active) {
          // Nothing to fly to: turn on the spot (three 120-degree steps) to let the camera and
          // the map catch up, then give up.
          if (spins_left < 0) spins_left = 3;
          if (spins_left == 0) {
            if (!memory.pendingRetry(t) && !tries.pendingRetry(t)) {
              R.end_reason = "explored";
              end = true;
            }  // else hover until a skipped target may be tried again
          } else if (uav.idle()) {
            --spins_left;
            uav.setPath({});
            uav.setYawTarget(wrapAngle(uav.pose().yaw + 2.0 * kPi / 3.0));
          }
        }
      }
      if (g.active) {
        double remaining = 0.0;
        // Face the viewpoint's yaw for the last metre; the direction of travel before.
        remaining = (uav.pose().position - g.vp.position).norm();
        if (remaining < 1.0 || uav.pathDone())
          uav.setYawTarget(g.vp.yaw);
        else
          uav.clearYawTarget();
      }
    } else if (approaching && !end) {
      if ((uav.pose().position - approach.position).norm() < 1.0 || uav.pathDone())
        uav.setYawTarget(approach.yaw);
      else
        uav.clearYawTarget();
      const InflatedMap inflated(grid, std::min(cfg.sim.uav.radius + 0.1, path_clearance));
      if (!uav.pathDone() && pathBlocked(inflated, uav.remainingPath(), 4.0)) {
        // The map now shows an obstacle on the way: choose again. A transit cut short this way
        // is no try of the object: it is planned again from here (house_6 "toilet": the transits
        // to the bathroom were blocked at the same door each time and the toilet never reached).
        if (transit) tries.transitBlocked(approach_object);
        approaching = transit = false;
        uav.setPath({});
      } else if (uav.pathDone() && (uav.pose().position - approach.position).norm() > ep.goal_tolerance) {
        approaching = transit = false;  // dropped (collision): re-plan
        failObject(approach_object);
      }
    }
    times.add("planning", plan_sw.ms());

    R.time_s = t;
    R.path_length_m = uav.distanceTravelled();
    R.collisions = uav.collisions();
    if (progress) progress(R);
    if (end) break;
    if (t >= ep.max_time_s) {
      R.end_reason = "time_budget";
      break;
    }
    if (ep.max_distance_m > 0 && uav.distanceTravelled() >= ep.max_distance_m) {
      R.end_reason = "distance_budget";
      break;
    }
    const Pose before = uav.pose();
    if (!uav.step(sim.groundTruth(), dt)) {
      g.active = false;  // collision: the UAV dropped its path
      if (std::getenv("USSNAV_DEBUG_EPISODE")) printCollision(t, before.position, approaching, g.path, mapper.grid(), sim.groundTruth());
      if (ep.end_on_collision) {
        R.end_reason = "collision";
        t += dt;
        R.collisions = uav.collisions();
        break;
      }
    }
    t += dt;
  }

  R.time_s = t;
  R.path_length_m = uav.distanceTravelled();
  R.collisions = uav.collisions();
  R.spl = R.success && R.shortest_path_m >= 0 ? splOf(true, R.path_length_m, std::max(R.shortest_path_m, 1e-6)) : 0.0;
  nlohmann::json stages = mapper.times().summary();
  const nlohmann::json mine = times.summary();
  for (auto it = mine.begin(); it != mine.end(); ++it) stages[it.key()] = it.value();
  R.stage_ms = stages;
  const double med = times.median("frame_update");
  R.update_hz = med > 0 ? 1000.0 / med : 0.0;
  run.graph = buildSceneGraph(mapper, t, spec.world_name);
  R.reasoning = {{"instruction", instruction.text}, {"targets", instruction.targets}, {"room", instruction.room},
                 {"interpreted", instruction.how}};
  if (decider) R.reasoning.update(decider->report());
  if (labeler) {
    labeler->offer(summarizeRegions(run.graph), 1e18);  // label the final regions too
    labeler->drain();
    const auto ls = labeler->stats();
    R.reasoning["reasoner"] = reasoner->name();
    R.reasoning["labels"] = {{"requests", ls.requests}, {"cache_hits", ls.cache_hits}, {"dropped", ls.dropped},
                             {"fallbacks", ls.fallbacks}, {"label_ms", latencySummary(ls.latency_ms)}};
    const auto sem = labeler->semantics();
    for (SgRegion& r : run.graph.regions)
      if (auto it = sem.find(r.id); it != sem.end()) r.label = it->second.label, r.description = it->second.description;
    const RegionLabelQuality lq =
        regionLabelQuality(run.graph, sim.world(), [&](const std::string& name) { return priors->roomIndex(name); });
    R.labels_scored = lq.scored;
    R.labels_correct = lq.correct;
    R.region_labels = {{"regions", lq.regions}, {"labelled", lq.labelled}, {"scored", lq.scored},
                       {"correct", lq.correct}, {"accuracy", lq.accuracy}, {"confusions", lq.confusions}};
  }
  R.reasoner_fallbacks = decider ? decider->stats().fallbacks : 0;
  run.topdown = drawEpisode(spec.world, run, camera, truth.instances, start);
  R.wall_s = wall.ms() / 1000.0;
  return run;
}

}  // namespace ussnav
