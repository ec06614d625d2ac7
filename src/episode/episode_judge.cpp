// The evaluation's view of an episode's goal (see episode_judge.hpp).

#include "ussnav/episode/episode_judge.hpp"

#include <algorithm>
#include <map>

#include "ussnav/episode/approach.hpp"

namespace ussnav {

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
      const Vec3 to = o->box.center - q;
      const GroundTruthGrid::Hit hit = gt.raycast(q, to.normalized(), to.norm() + 0.1);
      if (!hit.hit || gt.instanceOfLabel(hit.label) != o->id) continue;
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

bool judgeFound(const GroundTruthGoal& g, const Pose& pose, const DepthFrame& frame, double found_radius, int min_pixels) {
  std::map<int, int> pixels;
  for (uint16_t id : frame.instance)
    if (id) ++pixels[id];
  for (const Object* o : g.instances)
    if (o->box.distance(pose.position) <= found_radius && pixels[o->id] >= min_pixels) return true;
  return false;
}

}  // namespace ussnav
