// FlightLoop's exploration (flight_loop.hpp): looking around at take-off (and, with
// episode.look_again_m, at viewpoints far from where it last did), and flying to the
// targets the planner chooses (frontiers, camera-unseen patches) until none is left.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "flight_loop.hpp"
#include "ussnav/episode/episode_debug.hpp"
#include "ussnav/episode/exploration_targets.hpp"
#include "ussnav/mapping/inflated_map.hpp"

namespace ussnav {

void FlightLoop::lookAround() {
  // Three 120-degree turns on the spot, the goal approached as soon as it is seen
  // (chooseObject), then the first plan.
  if (look_steps_ > 0 && uav_.idle() && --look_steps_ > 0) {
    uav_.setPath({});
    uav_.setYawTarget(wrapAngle(uav_.pose().yaw + 2.0 * kPi / 3.0));
  }
}

bool FlightLoop::needReplan(const char*& why) {
  bool need = !g_.active || uav_.pathDone();
  why = !g_.active ? "no target" : "path done";  // debug output only
  if (g_.active && uav_.pathDone()) {
    const double dyaw = std::abs(wrapAngle(g_.vp.yaw - uav_.pose().yaw));
    const double off = (uav_.pose().position - g_.vp.position).norm();
    need = dyaw < 0.05 || off > ep_.goal_tolerance;  // turned, or dropped
    if (need && off <= ep_.goal_tolerance) {
      // Reached the viewpoint: whatever is left of its target is not visible from here.
      if (g_.kind == TargetKind::Unseen) camera_.abandon(g_.patch_cells);
      const bool second = ep_.close_look && g_.kind == TargetKind::Frontier && !memory_.lookedFrom(g_.centroid);
      if (second) {
        memory_.addLooked(g_.centroid, uav_.pose().position);
        ++R_.close_looks;
      } else {
        memory_.skipForGood(g_.centroid);
      }
      if (debug_)
        std::fprintf(stderr, "[t=%.1f] reached but %s target still open (%.2f %.2f %.2f)%s\n", t_, toString(g_.kind),
                     g_.centroid.x(), g_.centroid.y(), g_.centroid.z(), second ? ": a closer look next" : "");
    }
    // episode.look_again_m: at a viewpoint far from every spot turned round at, turn round
    // again before the next plan (the LiDAR maps all round, the camera sees 87 degrees).
    if (need && off <= ep_.goal_tolerance && ep_.look_again_m > 0.0) {
      const Vec3 here = uav_.pose().position;
      const bool far = std::all_of(look_spots_.begin(), look_spots_.end(),
                                   [&](const Vec3& s) { return (s - here).head<2>().norm() >= ep_.look_again_m; });
      if (far) {  // look first, then plan from here (the turn may show the goal)
        look_spots_.push_back(here), look_steps_ = 4;
        uav_.setPath({});
        g_.active = false;
        need = false;
        if (debug_) std::fprintf(stderr, "[t=%.1f] looking round again at (%.2f %.2f)\n", t_, here.x(), here.y());
      }
    }
  }
  if (g_.active && !need && t_ - last_check_ >= ep_.replan_period_s) {
    last_check_ = t_;
    // Target still there?
    bool alive = false;
    if (g_.kind == TargetKind::Frontier) {
      for (const Frontier& fr : frontiers_.frontiers())
        if ((fr.centroid - g_.centroid).norm() < 1.0) alive = true;
    } else {
      int unseen = 0;
      for (const Vec2i& c : g_.patch_cells) unseen += !camera_.isSeen(c);
      alive = unseen >= std::max(1, cfg_.exploration.unseen_min_cells / 2);
    }
    if (!alive) need = true, why = "target gone or moved";
  }
  if (g_.active && !need && !uav_.pathDone()) {
    // Every frame: the next metres of the path against what the map knows now.
    const double margin = std::min(cfg_.sim.uav.radius + 0.1, path_clearance_);
    const InflatedMap inflated(mapper_.grid(), margin);
    if (const auto at = blockedAt(inflated, uav_.remainingPath(), 4.0)) {
      need = true, why = "path blocked";
      const int added = rememberObstacle(*at, margin);
      if (debug_)
        std::fprintf(stderr, "[t=%.1f] path blocked at (%.2f %.2f %.2f), %d obstacle voxels remembered\n", t_, at->x(),
                     at->y(), at->z(), added);
    }
  }
  if (need && spins_left_ > 0 && !uav_.idle()) need = false;  // finish the current spin step
  return need;
}

bool FlightLoop::explore() {
  const char* why = "";
  const bool end = needReplan(why) && replan(why);
  if (g_.active) faceViewpoint();
  return end;
}

bool FlightLoop::replan(const char* why) {
  const ConnectivityGraph& graph = mapper_.graph();
  last_check_ = t_;
  const std::vector<UnseenPatch> patches = camera_.patches();
  targets_ = collectTargets(frontiers_, patches, memory_, t_, graph, mapper_.grid(), cfg_.exploration, ep_.close_look,
                            flight_z_, debug_);
  if (debug_)
    std::fprintf(stderr,
                 "[t=%.1f] replan (%s): frontiers %zu (cells %zu) patches %zu targets %zu blacklist %zu spins %d\n", t_,
                 why, frontiers_.frontiers().size(), frontiers_.cellCount(), patches.size(), targets_.size(),
                 memory_.size(), spins_left_);
  for (ExplorationTarget& tg : targets_) {
    const int node = mapper_.anchorNode(tg.viewpoints.front().position);
    tg.region = node >= 0 ? mapper_.regions().regionOf(node) : -1;
  }
  if (decider_) refreshSemantics();
  g_.active = false;
  uav_.setPath({});  // hover unless a new path is found below
  while (!targets_.empty() && graph.size() > 0) {
    PlanInput in;
    in.graph = &graph;
    in.map = &mapper_.grid();
    in.uav = uav_.pose();
    in.time = t_;
    in.targets = &targets_;
    in.uav_cfg = &cfg_.sim.uav;
    in.episode_cfg = &ep_;
    in.region_of = [&](int node) { return mapper_.regions().regionOf(node); };
    const PlanChoice choice = planner_->choose(in);
    if (choice.target < 0) break;
    ++R_.replans;
    const ExplorationTarget& tg = targets_[size_t(choice.target)];
    const Viewpoint& vp = tg.viewpoints[size_t(choice.viewpoint)];
    const auto p = flightPath(uav_.pose().position, vp.position);
    if (p && debug_) printPlan(tg, vp, *p, choice, decider_.get(), targets_);
    if (p) {
      g_.active = true;
      g_.kind = tg.kind;
      g_.centroid = tg.centroid;
      g_.vp = vp;
      g_.vp.position = p->back();  // the goal may have moved out of the clearance margin
      g_.path = *p;
      g_.patch_cells.clear();
      if (tg.kind == TargetKind::Unseen) g_.patch_cells = patches[size_t(tg.source_id)].cells;
      uav_.setPath(*p);
      path_clearance_ = last_clearance_;
      spins_left_ = -1;
      return false;
    }
    ++R_.unreachable;
    const int times = memory_.skipUnreachable(tg.centroid, t_, ep_.blacklist_s);
    if (debug_)
      std::fprintf(stderr, "[t=%.1f] unreachable (%.2f %.2f %.2f) x%d\n", t_, tg.centroid.x(), tg.centroid.y(),
                   tg.centroid.z(), times + 1);
    targets_.erase(targets_.begin() + choice.target);
  }
  // Nothing to fly to: turn on the spot (three 120-degree steps) to let the camera and the map
  // catch up, then give up.
  if (spins_left_ < 0) spins_left_ = 3;
  if (spins_left_ == 0) {
    // Give up unless a skipped target may be tried again: then hover until it may.
    if (memory_.pendingRetry(t_) || tries_.pendingRetry(t_)) return false;
    R_.end_reason = "explored";
    return true;
  }
  if (uav_.idle()) {
    --spins_left_;
    uav_.setPath({});
    uav_.setYawTarget(wrapAngle(uav_.pose().yaw + 2.0 * kPi / 3.0));
  }
  return false;
}

void FlightLoop::faceViewpoint() {
  // Face the viewpoint's yaw for the last metre; the direction of travel before.
  const double remaining = (uav_.pose().position - g_.vp.position).norm();
  if (remaining < 1.0 || uav_.pathDone())
    uav_.setYawTarget(g_.vp.yaw);
  else
    uav_.clearYawTarget();
}

}  // namespace ussnav
