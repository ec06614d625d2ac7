#include "support/scene_flight.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ussnav::test {

void SceneFlight::frame(const BoxScene& scene, const Vec3& p, double yaw) {
  grid.moveTo(p);
  grid.insertScan(renderScan(scene, p, 20000, lidar_vmin_deg, 52.0, 40.0));
  if (depth)
    grid.insertDepth(
        renderDepth(scene, Intrinsics::fromFov(80, 60, deg2rad(87), deg2rad(58)), cameraPose(p, yaw), 6.0));
  std::vector<Vec3i> occ;
  for (const VoxelChange& c : grid.changes())
    if (c.after == VoxelState::Occupied) occ.push_back(c.key);
  graph.update(grid, p, t, occ);
  grid.clearChanges();
  t += 0.1;
}

void SceneFlight::fly(const BoxScene& scene, const Vec3& a, const Vec3& b, double yaw) {
  const int n = std::max(1, int(std::ceil((b - a).norm() / 0.25)));
  for (int i = 0; i <= n; ++i) frame(scene, a + (b - a) * (double(i) / n), yaw);
}

}  // namespace ussnav::test
