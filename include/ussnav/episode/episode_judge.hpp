#pragma once
// Evaluation only (the flight loop never reads it): the ground truth of an episode's goal, from
// the simulator's world. Which instances satisfy the goal, L* (the shortest flight from the
// start to a success pose: a free cell within found_radius of an instance's box that sees it)
// and the split (multi-room: no instance in the start room; in worlds without rooms, L* > 8 m),
// and whether a frame counts as finding an instance (DESIGN.md's success rule). For the
// evaluation's split of a path into search and approach: whether an object the UAV mapped is a
// goal instance, and the shortest flight from any point to a success pose.

#include <functional>
#include <string>
#include <vector>

#include "ussnav/core/frame.hpp"
#include "ussnav/episode/goal.hpp"
#include "ussnav/sim/simulator.hpp"

namespace ussnav {

struct GroundTruthGoal {
  std::vector<const Object*> instances;
  double shortest_path = -1.0;  // L*, m; -1 when no success pose is reachable
  bool multi_room = false;
  std::vector<Vec2> success_cells;  // x-y of the success poses (free cells seeing an instance)
};

// `in_room`: the goal's room constraint on the ground-truth room type (always true without one).
GroundTruthGoal evaluateGoal(const Simulator& sim, const GoalMatcher& goal, const Pose& start, double found_radius,
                             const std::function<bool(const std::string&)>& in_room);

// A mapped object whose centroid lies this close to a goal instance's box is that instance.
constexpr double kSightingRadius = 1.0;  // m

// True when `p` (a mapped object's centroid) lies within `radius` of a goal instance's box.
bool nearGoalInstance(const GroundTruthGoal& g, const Vec3& p, double radius);

// The shortest flight from `from` (x-y) to a success pose, m; -1 when none is reachable.
double shortestToSuccess(const Simulator& sim, const GroundTruthGoal& g, const Vec2& from);

// The shortest flight from `from` (x-y) to a point at flight height within `range` (the
// detector's reach) of a goal instance's box with a line of sight to its centre or its top face
// (its centre and four points towards its edges): about the least search any planner could do
// before the goal can be seen (the camera's field of view and the mask rules are left out; a
// mask's median depth, not its nearest point, counts for the detector). -1 when no such point
// is reachable.
double shortestToView(const Simulator& sim, const GroundTruthGoal& g, const Vec2& from, double range);

// A goal instance within found_radius of the pose and at least min_pixels of it in the frame.
bool judgeFound(const GroundTruthGoal& g, const Pose& pose, const DepthFrame& frame, double found_radius, int min_pixels);

}  // namespace ussnav
