// Flying a saved route on a live map (see route_flight.hpp).

#include "ussnav/episode/route_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "ussnav/core/error.hpp"
#include "ussnav/episode/flight_path.hpp"
#include "ussnav/episode/search_memory.hpp"
#include "ussnav/mapping/inflated_map.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/uav.hpp"

namespace ussnav {
namespace {

constexpr double kStep = 0.25;  // m between the route samples tried as a leg's end
constexpr size_t kMaxTries = 6;

double remainingLength(const Uav& uav) {
  const std::vector<Vec3> rest = uav.remainingPath();
  double len = 0.0;
  for (size_t i = 1; i < rest.size(); ++i) len += (rest[i] - rest[i - 1]).norm();
  return len;
}

}  // namespace

RouteFlight flyRoute(Simulator& sim, const Config& cfg, const Pose& start, const std::vector<Vec3>& route,
                     const RouteFlightOptions& opt) {
  if (route.empty()) throw InputError("route", "", "expected at least one point to fly to");
  const EpisodeConfig& ep = cfg.episode;
  MapperOptions mopt;
  mopt.objects = false;
  mopt.regions = false;
  Mapper mapper(cfg, mopt);
  Uav uav(cfg.sim.uav, start);
  const FlightSettings flight = flightSettings(cfg, start.position.z());
  const double dt = 1.0 / cfg.sim.frame_rate_hz;
  const double replan_period = opt.replan_period_s > 0.0 ? opt.replan_period_s : ep.replan_period_s;

  // Route points at flight height; along[i]: route length from the first point to point i.
  std::vector<Vec3> pts = route;
  for (Vec3& p : pts) p.z() = start.position.z();
  std::vector<double> along(pts.size(), 0.0);
  for (size_t i = 1; i < pts.size(); ++i) along[i] = along[i - 1] + (pts[i] - pts[i - 1]).norm();
  auto pointAt = [&](double s) {
    const size_t i = size_t(std::upper_bound(along.begin(), along.end(), s) - along.begin());
    if (i >= pts.size()) return pts.back();
    if (i == 0) return pts.front();
    const double seg = along[i] - along[i - 1];
    return seg > 0.0 ? Vec3(pts[i - 1] + (pts[i] - pts[i - 1]) * ((s - along[i - 1]) / seg)) : pts[i];
  };
  const Vec3 prev_to_end = pts.size() >= 2 ? pts[pts.size() - 2] : start.position;

  RouteFlight R;
  R.end = pts.back();
  double done = 0.0;         // route length flown: the UAV's nearest route sample ahead, within the lookahead
  bool final_leg = false;    // the path being flown ends at R.end
  double last_check = 0.0, last_try = -1.0, stalled_since = -1.0, t = 0.0;
  double path_margin = ep.clearance;  // of the path being flown
  // Obstacles that blocked a path, kept clear of once the rolling window forgets them (as in an
  // episode's flight loop): else the same blocked path comes back when the UAV turns round.
  BlockingObstacles blocked;
  auto plan = [&](const Vec3& goal) -> std::optional<FlightPlan> {
    FlightPathOptions fo = flight.options;
    fo.avoid = blocked.forgotten(mapper.grid());
    auto p = planFlightPathLadder(mapper.graph(), mapper.grid(), uav.pose().position, goal, fo, flight.clearances);
    if (p && std::getenv("USSNAV_DEBUG_PATH")) {
      std::fprintf(stderr, "  path to (%.2f %.2f), margin %.2f%s:", goal.x(), goal.y(), p->clearance, p->through_unknown ? ", through unknown" : "");
      for (const Vec3& q : p->path) std::fprintf(stderr, " (%.2f %.2f %.2f)", q.x(), q.y(), q.z());
      std::fprintf(stderr, "\n");
    }
    if (p) {
      path_margin = p->clearance;
      ++R.legs;
      R.narrow_legs += p->clearance < ep.clearance;
    }
    return p;
  };

  while (true) {
    const SensedFrame f = sim.sense(uav.pose(), t);
    mapper.process(MapperFrame{f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
    const Vec3 at = uav.pose().position;
    {
      double best = (pointAt(done) - at).norm();
      for (double s = done + 0.1; s <= std::min(along.back(), done + opt.lookahead_m) + 1e-9; s += 0.1)
        if (const double d = (pointAt(s) - at).norm(); d < best) best = d, done = s;
    }
    // Near the end is arrival, whether or not the path's last point is reached: a new path from
    // inside the clearance margin would first step out of it, and the next come back.
    if (final_leg && (R.end - at).norm() <= ep.goal_tolerance + 0.2) {
      R.arrived = true;
      R.end_reason = "arrived";
      break;
    }
    if (t >= ep.max_time_s) {
      R.end_reason = "time_budget";
      break;
    }
    // A new leg when the path is flown (or nearly: an intermediate leg hands over 1 m before its
    // end, so the UAV does not stop at every leg), or when the map shows it blocked. Not on a
    // timer: a path from the UAV's position starts at the graph node nearest to it, often behind
    // it, and re-planning every period turned the UAV round every time.
    // While stalled (no safe path yet), try again every 0.5 s rather than every frame.
    bool replan = (uav.pathDone() && (stalled_since < 0.0 || t - last_try >= 0.5)) ||
                  (!final_leg && !uav.pathDone() && remainingLength(uav) < 1.0);
    if (!replan && t - last_check >= replan_period) {
      last_check = t;
      const double margin = std::min(cfg.sim.uav.radius + 0.1, path_margin);
      const InflatedMap inflated(mapper.grid(), margin);
      if (const auto hit = blockedAt(inflated, uav.remainingPath(), 4.0)) {
        replan = true;
        ++R.blocked;
        R.remembered_obstacles += blocked.addBlockedAt(mapper.grid(), *hit, margin);
      }
    }
    if (replan) {
      last_try = t;
      // The furthest point of the route within the lookahead that a safe path reaches, sampled
      // every kStep m: a route point beyond a door may still be unknown to the live map while
      // the doorway before it is seen free; flying there shows the room.
      bool found = false;
      const double s_end = along.back(), s_max = std::min(s_end, done + opt.lookahead_m);
      std::vector<double> samples;
      for (double s = done + kStep; s < s_max - 1e-9; s += kStep) samples.push_back(s);
      samples.push_back(s_max);
      // At most kMaxTries of them, furthest first (a failed search can cost a voxel A* over
      // the window); while stalled, the furthest and the nearest only.
      const size_t stride = stalled_since >= 0.0 ? std::max<size_t>(1, samples.size() - 1)
                                                 : (samples.size() + kMaxTries - 1) / kMaxTries;
      std::vector<size_t> order;  // sample indices, furthest first, the nearest always
      for (size_t k = samples.size(); k-- > 0;)
        if ((samples.size() - 1 - k) % stride == 0 || k == 0) order.push_back(k);
      for (const size_t k : order) {
        if (found) break;
        if (samples[k] >= s_end - 1e-9) {
          // The goal itself, walked back towards the point before it until a path reaches it.
          const Vec3 back = prev_to_end - pts.back();
          const double len = back.norm();
          for (int i = 0; i <= 5 && !found; ++i) {
            const double w = std::min(0.2 * i, len);
            const Vec3 g = len > 0.0 ? Vec3(pts.back() + back * (w / len)) : pts.back();
            if (auto p = plan(g)) {
              uav.setPath(p->path);
              R.end = g;
              final_leg = found = true;
            }
            if (w >= len) break;
          }
        } else if ((pointAt(samples[k]) - at).norm() <= opt.reach_m) {
          break;  // a leg that goes nowhere: the UAV is as far along as a safe path reaches
        } else if (auto p = plan(pointAt(samples[k]))) {
          uav.setPath(p->path);
          final_leg = false;
          found = true;
        }
      }
      if (std::getenv("USSNAV_DEBUG_PATH"))
        std::fprintf(stderr, "[t=%.1f] route: at (%.2f %.2f %.2f), %.1f of %.1f m along, %s\n", t, at.x(), at.y(), at.z(), done,
                     along.back(), found ? (final_leg ? "final leg" : "leg") : "no safe path");
      if (found) {
        stalled_since = -1.0;
        uav.clearYawTarget();
      } else {
        // Hover and look: first along the route, then round, so the camera maps
        // what the LiDAR's narrow vertical field left unknown (a door's edges, the floor beyond).
        uav.setPath({});
        if (stalled_since < 0.0) stalled_since = t;
        const Vec3 d = pointAt(std::min(along.back(), done + 1.0)) - at;
        const double stalled = t - stalled_since;
        uav.setYawTarget(std::atan2(d.y(), d.x()) + (stalled < 2.0 ? 0.0 : 1.6 * std::floor(stalled / 2.0)));
        if (t - stalled_since >= opt.stall_s) {
          R.end_reason = "no_safe_path";
          break;
        }
      }
    }
    if (!uav.step(sim.groundTruth(), dt)) {
      R.end_reason = "collision";
      break;
    }
    t += dt;
  }
  R.time_s = t;
  R.path_length_m = uav.distanceTravelled();
  R.collisions = uav.collisions();
  R.end_shift_m = (R.end - pts.back()).norm();
  R.final_pose = uav.pose();
  return R;
}

}  // namespace ussnav
