#pragma once
// Debug output of the flight loop (USSNAV_DEBUG_EPISODE, docs/eval.md "Debugging an episode"):
// the target a re-plan chose, its flight path, and the coarse level's weighing of every region;
// and the map around a collision.

#include <vector>

#include "ussnav/exploration/planner.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/reasoning/coarse_decider.hpp"
#include "ussnav/sim/ground_truth.hpp"

namespace ussnav {

// To stderr: the chosen target and viewpoint, the path, the planner's note, the decider's
// reason and per-region scores (when `decider` is not null), and every candidate target.
void printPlan(const ExplorationTarget& chosen, const Viewpoint& vp, const std::vector<Vec3>& path,
               const PlanChoice& choice, const CoarseDecider* decider, const std::vector<ExplorationTarget>& targets);

// To stderr: where the UAV collided (`at`, the position before the step), the path it flew, and
// three slices (z -3, 0, +3 voxels) of the 9 x 9 voxels around it, map state against ground
// truth: '#' occupied and solid, 'o' occupied but free, '.' free, '!' free but solid, '?' unknown,
// 'U' unknown and solid.
void printCollision(double t, const Vec3& at, bool approaching, const std::vector<Vec3>& path, const RollingGrid& grid,
                    const GroundTruthGrid& truth);

}  // namespace ussnav
