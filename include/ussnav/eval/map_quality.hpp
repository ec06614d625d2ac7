#pragma once
// Quality of the mapping layers against the simulator's ground truth (evaluation only: the
// pipeline never reads ground truth). ObservedFreeSpace remembers every voxel the rolling grid
// has called Free in a height band (from its change log, so it outlives the window);
// skeletonQuality() measures the two numbers: free_space_coverage (the fraction of
// observed free voxels inside some polyhedron) and path_success (the fraction of random pairs of
// observed free points for which the graph gives a path that is collision-free in the ground
// truth).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/gt_paths.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

class ObservedFreeSpace {
 public:
  ObservedFreeSpace(double resolution, double z_min, double z_max);
  // Reads the grid's change log of the last frame.
  void update(const RollingGrid& grid);
  // Voxel centres whose last observed state was Free.
  std::vector<Vec3> freeCenters() const;
  size_t size() const { return free_.size(); }

 private:
  double res_;
  int kz0_, kz1_;
  std::unordered_map<int64_t, uint8_t> free_;  // key -> 1 while Free
};

struct SkeletonQuality {
  double free_space_coverage = 0.0;  // observed free voxels inside some polyhedron
  // The same over the observed free voxels the UAV's centre can occupy (no ground-truth obstacle
  // within `radius`): the space a navigation graph must cover. Wall-side voxels are excluded.
  double navigable_coverage = 0.0;
  double path_success = 0.0;
  int observed_free_voxels = 0;
  int navigable_voxels = 0;
  int pairs = 0;
  double mean_path_ratio = 0.0;  // graph path length / ground-truth shortest, over successes
  int not_found = 0;   // pairs the graph gave no path for
  int colliding = 0;   // pairs whose graph path crosses occupied ground truth
};

// `pairs` random pairs (seeded) of observed free points that are safe for `radius` in the
// ground truth and joined by a ground-truth path.
SkeletonQuality skeletonQuality(const ConnectivityGraph& graph, const RollingGrid& grid,
                                const GroundTruthGrid& gt, const GtPlanner& planner,
                                const ObservedFreeSpace& observed, double radius, int pairs, uint64_t seed);

// True when the polyline does not pass through an occupied ground-truth voxel.
bool polylineCollisionFree(const GroundTruthGrid& gt, const std::vector<Vec3>& pts);

}  // namespace ussnav
