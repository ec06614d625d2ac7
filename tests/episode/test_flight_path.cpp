// planFlightPath's contract on a rolling window: no returned segment crosses what the window's
// inflated map shows blocked, also where a segment leaves the window (the flight loop rejects
// such a path as soon as it is flown, and re-planning returns the same one: the UAV hovers).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/scene_flight.hpp"
#include "ussnav/episode/flight_path.hpp"
#include "ussnav/mapping/inflated_map.hpp"

using namespace ussnav;

TEST(FlightPath, NoSegmentCrossesAnObstacleNearTheWindowEdge) {
  // A corridor closed at x = 6.6-6.8 by a wall with a 0.9 m door off its centre line. Mapped
  // flying through to x = 13 and back to x = 3, where the window ends at x = 7, just past the
  // door; the goals (x = 12) lie outside it.
  test::BoxScene scene = test::corridor(20.0, 3.0, 2.7);
  scene.solids.push_back(Aabb(Vec3(6.6, -1.6, 0.0), Vec3(6.8, 0.1, 2.7)));
  scene.solids.push_back(Aabb(Vec3(6.6, 1.0, 0.0), Vec3(6.8, 1.6, 2.7)));
  test::SceneFlight f(Vec3(1, 0, 1.2));
  auto fly = [&](const Vec3& a, const Vec3& b, double yaw) {
    const int n = int(std::ceil((b - a).norm() / 0.25));
    for (int i = 0; i <= n; ++i) f.frame(scene, a + (b - a) * (double(i) / n), yaw);
  };
  fly(Vec3(1, 0, 1.2), Vec3(6, 0.55, 1.2), 0.0);
  fly(Vec3(6, 0.55, 1.2), Vec3(7.4, 0.55, 1.2), 0.0);
  fly(Vec3(7.4, 0.55, 1.2), Vec3(13, 0, 1.2), 0.0);
  fly(Vec3(13, 0, 1.2), Vec3(7.4, 0.55, 1.2), kPi);
  fly(Vec3(7.4, 0.55, 1.2), Vec3(3, 0, 1.2), kPi);
  for (int i = 0; i < 4; ++i) f.frame(scene, Vec3(3, 0, 1.2), 0.0);
  ASSERT_TRUE(f.grid.inWindow(f.grid.keyOf(Vec3(6.9, 0.5, 1.2))));
  ASSERT_FALSE(f.grid.inWindow(f.grid.keyOf(Vec3(7.2, 0.5, 1.2))));

  const FlightPathOptions opt;
  const InflatedMap inflated(f.grid, opt.clearance, opt.z_min, opt.z_max);
  int planned = 0;
  for (double gy : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
    const auto p = planFlightPath(f.graph, f.grid, Vec3(3, 0, 1.2), Vec3(12, gy, 1.2), opt);
    if (!p) continue;
    ++planned;
    for (size_t i = 1; i < p->size(); ++i)
      EXPECT_FALSE(castRay(inflated, (*p)[i - 1], (*p)[i], false).blocked)
          << "goal y " << gy << ": segment " << i << " (" << (*p)[i - 1].transpose() << ") -> (" << (*p)[i].transpose()
          << ") crosses the inflated map";
  }
  std::printf("%d of 5 goals planned, graph %zu nodes\n", planned, f.graph.size());
}
