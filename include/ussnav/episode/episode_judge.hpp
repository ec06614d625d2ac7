#pragma once
// Evaluation only (the flight loop never reads it): the ground truth of an episode's goal, from
// the simulator's world. Which instances satisfy the goal, L* (the shortest flight from the
// start to a success pose: a free cell within found_radius of an instance's box that sees it)
// and the split (multi-room: no instance in the start room; in worlds without rooms, L* > 8 m),
// and whether a frame counts as finding an instance (DESIGN.md's success rule).

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
};

// `in_room`: the goal's room constraint on the ground-truth room type (always true without one).
GroundTruthGoal evaluateGoal(const Simulator& sim, const GoalMatcher& goal, const Pose& start, double found_radius,
                             const std::function<bool(const std::string&)>& in_room);

// A goal instance within found_radius of the pose and at least min_pixels of it in the frame.
bool judgeFound(const GroundTruthGoal& g, const Pose& pose, const DepthFrame& frame, double found_radius, int min_pixels);

}  // namespace ussnav
