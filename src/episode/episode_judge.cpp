// The evaluation's view of an episode's goal (see episode_judge.hpp).

#include "ussnav/episode/episode_judge.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "ussnav/episode/approach.hpp"

namespace ussnav {
namespace {

// The first thing on the ray from `from` to `target` (and 0.1 m past it) is instance `id`.
bool seesInstance(const GroundTruthGrid& gt, const Vec3& from, const Vec3& target, int id) {
  const Vec3 to = target - from;
  const GroundTruthGrid::Hit hit = gt.raycast(from, to.normalized(), to.norm() + 0.1);
  return hit.hit && gt.instanceOfLabel(hit.label) == id;
}

}  // namespace

GroundTruthGoal evaluateGoal(const Simulator& sim, const GoalMatcher& goal, const Pose& start, double found_radius,
                             const std::function<bool(const std::string&)>& in_room) {
  GroundTruthGoal g;
  const World& w = sim.world();
  g.instances = goalInstances(w, goal, in_room);
  if (g.instances.empty()) return g;
  const GtPlanner& planner = sim.planner();
  // Success poses: free cells within found_radius of a goal instance's box (approach poses may
  // sink up to 0.6 m below flight height or rise kApproachAbove above it, approach.hpp) from
  // which the instance is in sight.
  const GroundTruthGrid& gt = sim.groundTruth();
  std::vector<Vec2> goals;
  for (const Vec2& p : planner.freeSamples(2))
    for (const Object* o : g.instances) {
      const Vec3 q(p.x(), p.y(), std::clamp(o->box.center.z(), planner.flightZ() - 0.6, planner.flightZ() + kApproachAbove));
      if (o->box.distance(q) > found_radius) continue;
      if (!seesInstance(gt, q, o->box.center, o->id)) continue;
      goals.push_back(p);
      break;
    }
  g.success_cells = goals;
  g.shortest_path = shortestToSuccess(sim, g, start.position.head<2>());
  const Room* start_room = w.roomAt(start.position.head<2>());
  if (start_room) {
    g.multi_room = std::none_of(g.instances.begin(), g.instances.end(),
                                [&](const Object* o) { return o->room_id == start_room->id; });
  } else {
    g.multi_room = g.shortest_path > 8.0;  // worlds without rooms: far counts as multi-room
  }
  return g;
}

bool nearGoalInstance(const GroundTruthGoal& g, const Vec3& p, double radius) {
  return std::any_of(g.instances.begin(), g.instances.end(), [&](const Object* o) { return o->box.distance(p) <= radius; });
}

double shortestToSuccess(const Simulator& sim, const GroundTruthGoal& g, const Vec2& from) {
  if (g.success_cells.empty()) return -1.0;
  const auto path = sim.planner().shortestPath(from, g.success_cells);
  return path ? GtPlanner::length(*path) : -1.0;
}

double shortestToView(const Simulator& sim, const GroundTruthGoal& g, const Vec2& from, double range) {
  const GtPlanner& planner = sim.planner();
  const GroundTruthGrid& gt = sim.groundTruth();
  // Points of each instance a view may see: its centre, and its top face's centre and the
  // middles of the four half-planes towards its edges (a bed's foot, a table's near side).
  std::vector<std::vector<Vec3>> marks;
  for (const Object* o : g.instances) {
    const OrientedBox& b = o->box;
    const double c = std::cos(b.yaw), s = std::sin(b.yaw), top = b.center.z() + b.half_extents.z() - 0.02;
    std::vector<Vec3> m{b.center, Vec3(b.center.x(), b.center.y(), top)};
    for (const auto& [u, v] : {std::pair{0.7, 0.0}, {-0.7, 0.0}, {0.0, 0.7}, {0.0, -0.7}}) {
      const double lx = u * b.half_extents.x(), ly = v * b.half_extents.y();
      m.emplace_back(b.center.x() + c * lx - s * ly, b.center.y() + s * lx + c * ly, top);
    }
    marks.push_back(std::move(m));
  }
  std::vector<Vec2> views;
  for (const Vec2& p : planner.freeSamples(2)) {
    const Vec3 q(p.x(), p.y(), planner.flightZ());
    bool seen = false;
    for (size_t i = 0; i < g.instances.size() && !seen; ++i)
      if (g.instances[i]->box.distance(q) <= range)
        seen = std::any_of(marks[i].begin(), marks[i].end(),
                           [&](const Vec3& target) { return seesInstance(gt, q, target, g.instances[i]->id); });
    if (seen) views.push_back(p);
  }
  if (views.empty()) return -1.0;
  const auto path = planner.shortestPath(from, views);
  return path ? GtPlanner::length(*path) : -1.0;
}

bool judgeFound(const GroundTruthGoal& g, const Pose& pose, const DepthFrame& frame, double found_radius, int min_pixels) {
  std::map<int, int> pixels;
  for (uint16_t id : frame.instance)
    if (id) ++pixels[id];
  for (const Object* o : g.instances)
    if (o->box.distance(pose.position) <= found_radius && pixels[o->id] >= min_pixels) return true;
  return false;
}

}  // namespace ussnav
