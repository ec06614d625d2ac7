#pragma once
// A UAV mapping an analytic BoxScene frame by frame, as the episode does: each frame moves the
// rolling window to the pose, inserts a LiDAR-like scan and a depth image rendered from it, and
// updates the connectivity graph with the voxels that became occupied. For tests that need a
// mapped world and its graph without the simulator (approach poses, flight paths).

#include "support/mapping_scenes.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav::test {

struct SceneFlight {
  RollingGrid grid;
  ConnectivityGraph graph;
  double t = 0.0;  // simulated time of the next frame, s (10 Hz)
  double lidar_vmin_deg = -52.0;  // lowest beam; the paper's Mid-360 starts at -7 deg
  bool depth = true;              // insert the depth image too

  explicit SceneFlight(const Vec3& start) : grid(GridConfig{}, start) {}
  // One frame at `p` facing `yaw` (radians).
  void frame(const BoxScene& scene, const Vec3& p, double yaw);
  // Frames every 0.25 m (or less) along the straight line a -> b, both ends included.
  void fly(const BoxScene& scene, const Vec3& a, const Vec3& b, double yaw);
};

}  // namespace ussnav::test
