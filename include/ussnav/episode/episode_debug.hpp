#pragma once
// Debug output of the flight loop (USSNAV_DEBUG_EPISODE, docs/eval.md "Debugging an episode"):
// the target a re-plan chose, its flight path, and the coarse level's weighing of every region.

#include <vector>

#include "ussnav/exploration/planner.hpp"
#include "ussnav/reasoning/coarse_decider.hpp"

namespace ussnav {

// To stderr: the chosen target and viewpoint, the path, the planner's note, the decider's
// reason and per-region scores (when `decider` is not null), and every candidate target.
void printPlan(const ExplorationTarget& chosen, const Viewpoint& vp, const std::vector<Vec3>& path,
               const PlanChoice& choice, const CoarseDecider* decider, const std::vector<ExplorationTarget>& targets);

}  // namespace ussnav
