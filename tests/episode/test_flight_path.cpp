// planFlightPath's contract on a rolling window: no returned segment crosses what the window's
// inflated map shows blocked, also where a segment leaves the window (the flight loop rejects
// such a path as soon as it is flown, and re-planning returns the same one: the UAV hovers).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "support/scene_flight.hpp"
#include "ussnav/episode/flight_path.hpp"
#include "ussnav/mapping/inflated_map.hpp"
#include "ussnav/skeleton/grid_path.hpp"

using namespace ussnav;

namespace {

void addBox(test::BoxScene& s, double x0, double y0, double z0, double x1, double y1, double z1) {
  s.solids.push_back(Aabb(Vec3(x0, y0, z0), Vec3(x1, y1, z1)));
}

// A hall x -0.2-14.0, y -2.2-2.2, 2.7 m high, for a block to stand in.
test::BoxScene hall() {
  test::BoxScene s;
  addBox(s, -0.5, -2.6, -0.2, 14.5, 2.6, 0.0);  // floor
  addBox(s, -0.5, -2.6, 2.7, 14.5, 2.6, 2.9);   // ceiling
  addBox(s, -0.4, -2.4, 0.0, 14.2, -2.2, 2.7);  // south wall
  addBox(s, -0.4, 2.2, 0.0, 14.2, 2.4, 2.7);    // north wall
  addBox(s, -0.4, -2.2, 0.0, -0.2, 2.2, 2.7);   // west wall
  addBox(s, 14.0, -2.2, 0.0, 14.2, 2.2, 2.7);   // east wall
  return s;
}

// From q to the nearest true solid of the scene.
double distanceToSolids(const test::BoxScene& s, const Vec3& q) {
  double d = 1e9;
  for (const Aabb& box : s.solids) d = std::min(d, (q - q.cwiseMax(box.min).cwiseMin(box.max)).norm());
  return d;
}

}  // namespace

TEST(FlightPath, NoSegmentCrossesAnObstacleNearTheWindowEdge) {
  // A corridor closed at x = 6.6-6.8 by a wall with a 0.9 m door off its centre line. Mapped
  // flying through to x = 13 and back to x = 3, where the window ends at x = 7, just past the
  // door; the goals (x = 12) lie outside it.
  test::BoxScene scene = test::corridor(20.0, 3.0, 2.7);
  scene.solids.push_back(Aabb(Vec3(6.6, -1.6, 0.0), Vec3(6.8, 0.1, 2.7)));
  scene.solids.push_back(Aabb(Vec3(6.6, 1.0, 0.0), Vec3(6.8, 1.6, 2.7)));
  test::SceneFlight f(Vec3(1, 0, 1.2));
  f.fly(scene, Vec3(1, 0, 1.2), Vec3(6, 0.55, 1.2), 0.0);
  f.fly(scene, Vec3(6, 0.55, 1.2), Vec3(7.4, 0.55, 1.2), 0.0);
  f.fly(scene, Vec3(7.4, 0.55, 1.2), Vec3(13, 0, 1.2), 0.0);
  f.fly(scene, Vec3(13, 0, 1.2), Vec3(7.4, 0.55, 1.2), kPi);
  f.fly(scene, Vec3(7.4, 0.55, 1.2), Vec3(3, 0, 1.2), kPi);
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

TEST(FlightPath, DetoursInsideTheWindowKeepToSpaceSeenFree) {
  // A wall across a corridor at x = 5.0-5.2 with a 0.9 m door, mapped by the paper's LiDAR alone
  // (lowest beam -7 deg) from 1.5 m in front of it: the foot of the wall and of the door jambs
  // stays unseen, so nothing inflates it. Goals behind the door, seen free all around (as
  // frontier viewpoints are). A segment the inflated map blocks must not be replaced by a
  // detour through that unseen space (AWS hospital, "fridge": the UAV dived into a chair seat
  // and the foot of a wall this way); the old detour slid under the jambs' inflation at z 0.75.
  test::BoxScene scene = test::corridor(12.0, 3.0, 2.7);
  scene.solids.push_back(Aabb(Vec3(5.0, -1.6, 0.0), Vec3(5.2, -0.45, 2.7)));
  scene.solids.push_back(Aabb(Vec3(5.0, 0.45, 0.0), Vec3(5.2, 1.6, 2.7)));
  scene.solids.push_back(Aabb(Vec3(5.0, -0.45, 2.1), Vec3(5.2, 0.45, 2.7)));
  const Vec3 start(3.5, 0.0, 1.2);
  test::SceneFlight f(start);
  f.lidar_vmin_deg = -7.0;
  f.depth = false;
  for (int i = 0; i < 6; ++i) f.frame(scene, start, 0.0);
  ASSERT_EQ(f.grid.stateAt(Vec3(5.1, 0.6, 1.5)), VoxelState::Occupied);  // the jamb, seen
  ASSERT_EQ(f.grid.stateAt(Vec3(5.1, 0.6, 0.6)), VoxelState::Unknown);   // its foot, unseen

  auto seenFreeAround = [&](const Vec3& p) {
    const double r = 0.2, res = f.grid.resolution();
    for (double dz = -r; dz <= r + 1e-9; dz += res)
      for (double dy = -r; dy <= r + 1e-9; dy += res)
        for (double dx = -r; dx <= r + 1e-9; dx += res)
          if (f.grid.stateAt(p + Vec3(dx, dy, dz)) != VoxelState::Free) return false;
    return true;
  };
  // Default clearance 0.4: the inflated door is shut, and the old detour slid under the jambs'
  // inflation through their unseen foot. 0.35 (the episode's fallback, UAV radius + 0.1): the
  // door is open at flight height and every goal gets a path.
  for (const double clearance : {0.4, 0.35}) {
    FlightPathOptions opt;
    opt.clearance = clearance;
    int goals = 0, planned = 0;
    for (double gx = 5.6; gx < 8.0; gx += 0.4)
      for (double gy = -1.0; gy <= 1.0 + 1e-9; gy += 0.25)
        for (double gz : {0.9, 1.2, 1.5}) {
          const Vec3 goal(gx, gy, gz);
          if (!seenFreeAround(goal)) continue;
          ++goals;
          const auto p = planFlightPath(f.graph, f.grid, start, goal, opt);
          if (!p) continue;
          ++planned;
          for (size_t i = 1; i < p->size(); ++i) {
            const Vec3 &a = (*p)[i - 1], &b = (*p)[i];
            ASSERT_TRUE(f.grid.inWindow(f.grid.keyOf(a)) && f.grid.inWindow(f.grid.keyOf(b)));
            const RayHit h = castRay(f.grid, a, b, true);
            EXPECT_FALSE(h.blocked) << "clearance " << clearance << ", goal (" << goal.transpose() << "): segment ("
                                    << a.transpose() << ") -> (" << b.transpose()
                                    << ") crosses voxels the map has not seen free at (" << h.point.transpose() << ")";
          }
        }
    EXPECT_GE(goals, 5);
    if (clearance < 0.4) {
      EXPECT_EQ(planned, goals);
    }
  }
}

TEST(FlightPath, LadderPassesANarrowDoorIntoForgottenSpace) {
  // A room (y < 6.0) and a corridor (y 6.2-8.2) joined by a 0.8 m door at x = 6.18-6.98 next to
  // the room's east wall. The UAV comes down the corridor and through the door, flies into the
  // room's far corner, where the rolling window forgets the corridor, and comes back 2.5 m west
  // of the door: the door's jambs are mapped again, the corridor beyond them is not (AWS
  // hospital, "sofa": the UAV boxed in a ward ended the episode "explored"). The connectivity
  // graph still knows the corridor.
  test::BoxScene s;
  addBox(s, -0.5, -0.5, -0.2, 14.5, 8.6, 0.0);   // floor
  addBox(s, -0.5, -0.5, 2.7, 14.5, 8.6, 2.9);    // ceiling
  addBox(s, -0.2, -0.2, 0.0, 7.2, 0.0, 2.7);     // room, south wall
  addBox(s, -0.2, 0.0, 0.0, 0.0, 6.0, 2.7);      // room, west wall
  addBox(s, 6.98, 0.0, 0.0, 7.18, 6.0, 2.7);     // room, east wall
  addBox(s, -0.2, 6.0, 0.0, 6.18, 6.2, 2.7);     // wall west of the door
  addBox(s, 6.98, 6.0, 0.0, 14.2, 6.2, 2.7);     // wall east of the door (the corridor's south wall)
  addBox(s, -0.2, 8.2, 0.0, 14.2, 8.4, 2.7);     // corridor, north wall
  addBox(s, -0.4, 6.2, 0.0, -0.2, 8.2, 2.7);     // corridor, west end
  addBox(s, 14.0, 6.2, 0.0, 14.2, 8.2, 2.7);     // corridor, east end
  const double z = 1.2;
  test::SceneFlight f(Vec3(12.0, 7.2, z));
  f.fly(s, Vec3(12.0, 7.2, z), Vec3(6.58, 7.2, z), kPi);
  f.fly(s, Vec3(6.58, 7.2, z), Vec3(6.58, 4.5, z), -0.5 * kPi);
  f.fly(s, Vec3(6.58, 4.5, z), Vec3(2.0, 1.0, z), -0.75 * kPi);
  const Vec3 back(4.0, 4.9, z);
  f.fly(s, Vec3(2.0, 1.0, z), back, 0.6);
  const Vec3 goal(12.0, 7.2, z);
  ASSERT_EQ(f.grid.stateAt(Vec3(6.05, 6.1, z)), VoxelState::Occupied);  // the west jamb, mapped again
  ASSERT_EQ(f.grid.stateAt(Vec3(6.58, 7.0, z)), VoxelState::Unknown);   // the corridor beyond, forgotten
  ASSERT_GT(f.graph.size(), 0u);

  // Through seen-free space no margin passes; the old last resort (full margin, through unseen
  // voxels) does not either: the inflated jambs shut the door.
  const std::vector<double> clearances{0.4, 0.35, 0.3};
  FlightPathOptions opt;
  for (const bool unknown : {false, true})
    for (const double c : clearances) {
      opt.clearance = c;
      opt.detour_through_unknown = unknown;
      if (unknown && c < 0.4) continue;
      EXPECT_FALSE(planFlightPath(f.graph, f.grid, back, goal, opt).has_value()) << "clearance " << c;
    }

  const std::optional<FlightPlan> plan = planFlightPathLadder(f.graph, f.grid, back, goal, FlightPathOptions{}, clearances);
  ASSERT_TRUE(plan.has_value());
  EXPECT_DOUBLE_EQ(plan->clearance, 0.3);
  EXPECT_TRUE(plan->through_unknown);
  const InflatedMap inflated(f.grid, plan->clearance, opt.z_min, opt.z_max);
  bool through_door = false;
  for (size_t i = 1; i < plan->path.size(); ++i) {
    const Vec3 &a = plan->path[i - 1], &b = plan->path[i];
    EXPECT_FALSE(castRay(inflated, a, b, false).blocked) << "segment " << i << " crosses the inflated map";
    const int n = int(std::ceil((b - a).norm() / 0.05));
    for (int k = 0; k <= n; ++k) {
      const Vec3 q = a + (b - a) * (double(k) / n);
      const double d = distanceToSolids(s, q);
      ASSERT_GE(d, 0.25) << "the path passes " << d << " m from a wall at (" << q.transpose() << ")";
      if (q.y() > 6.0 && q.y() < 6.2) through_door = true;
    }
  }
  EXPECT_TRUE(through_door);
  EXPECT_NEAR(plan->path.back().x(), goal.x(), 0.6);
  EXPECT_NEAR(plan->path.back().y(), goal.y(), 0.6);
}

TEST(FlightPath, RouteComingBackIntoTheWindowPassesADoor) {
  // Two corridors joined at their west end around a solid block (x 1.8-14, y -0.6-0.6); the
  // south one has a wall at x = 10.0-10.2 with a 0.9 m door against the block. Mapped flying from
  // the south corridor's east end west through the door, round the block and east along the
  // north corridor, where the window (x 9-17) has forgotten the west end. The route to the south
  // corridor's east end leaves the window westwards and comes back into it through the door: a
  // segment that starts outside the window and that the inflated door blocks (office-4
  // "toilet": the frontiers of a room behind such a route "unreachable", then blacklisted).
  test::BoxScene s = hall();
  addBox(s, 1.8, -0.6, 0.0, 10.8, 0.6, 2.7);    // the block between the corridors, with a slit at
  addBox(s, 12.8, -0.6, 0.0, 14.0, 0.6, 2.7);   // x 10.8-12.8, z 1.0-1.4 (too low to fly through)
  addBox(s, 10.8, -0.6, 0.0, 12.8, 0.6, 1.0);   // through which the door is seen from the north
  addBox(s, 10.8, -0.6, 1.4, 12.8, 0.6, 2.7);   // corridor
  addBox(s, 10.0, -2.2, 0.0, 10.2, -1.5, 2.7);  // the door's jamb: the door is y -1.5 .. -0.6
  const double z = 1.2;
  test::SceneFlight f(Vec3(13.0, -1.4, z));
  f.fly(s, Vec3(13.0, -1.4, z), Vec3(10.6, -1.1, z), kPi);
  f.fly(s, Vec3(10.6, -1.1, z), Vec3(9.6, -1.1, z), kPi);
  f.fly(s, Vec3(9.6, -1.1, z), Vec3(0.8, -1.4, z), kPi);
  f.fly(s, Vec3(0.8, -1.4, z), Vec3(0.8, 1.4, z), 0.5 * kPi);
  f.fly(s, Vec3(0.8, 1.4, z), Vec3(13.0, 1.4, z), 0.0);
  for (int i = 0; i < 4; ++i) f.frame(s, Vec3(13.0, 1.4, z), -0.75 * kPi);
  const Vec3 here(13.0, 1.4, z), goal(12.5, -1.4, z);
  ASSERT_TRUE(f.grid.inWindow(f.grid.keyOf(Vec3(9.8, -1.1, z))));  // the door is in the window
  ASSERT_FALSE(f.grid.inWindow(f.grid.keyOf(Vec3(6.0, -1.4, z))));  // the corridor west of it is not
  ASSERT_FALSE(f.grid.inWindow(f.grid.keyOf(Vec3(0.8, 0.0, z))));
  ASSERT_TRUE(f.grid.inWindow(f.grid.keyOf(goal)));
  ASSERT_EQ(f.grid.stateAt(Vec3(10.15, -1.55, z)), VoxelState::Occupied);  // the jamb, seen through the slit

  for (const double clearance : {0.4, 0.35, 0.3}) {
    FlightPathOptions opt;
    opt.clearance = clearance;
    const auto p = planFlightPath(f.graph, f.grid, here, goal, opt);
    ASSERT_TRUE(p.has_value()) << "clearance " << clearance;
    const InflatedMap inflated(f.grid, clearance, opt.z_min, opt.z_max);
    bool west = false;
    for (size_t i = 1; i < p->size(); ++i) {
      const Vec3 &a = (*p)[i - 1], &b = (*p)[i];
      EXPECT_FALSE(castRay(inflated, a, b, false).blocked)
          << "clearance " << clearance << ": segment " << i << " (" << a.transpose() << ") -> (" << b.transpose()
          << ") crosses the inflated map";
      west = west || b.x() < 1.8;
      const int n = int(std::ceil((b - a).norm() / 0.05));
      for (int k = 0; k <= n; ++k) {
        const Vec3 q = a + (b - a) * (double(k) / n);
        if (!f.grid.inWindow(f.grid.keyOf(q))) continue;  // checked again when the window gets there
        const double d = distanceToSolids(s, q);
        ASSERT_GE(d, 0.25) << "clearance " << clearance << ": the path passes " << d << " m from a wall at ("
                           << q.transpose() << ")";
      }
    }
    EXPECT_TRUE(west) << "the route goes round the block";
    EXPECT_NEAR(p->back().x(), goal.x(), 0.6);
    EXPECT_NEAR(p->back().y(), goal.y(), 0.6);
  }
}

TEST(FlightPath, PlacesFoundBlockedBeyondTheWindowAreAvoided) {
  // A ring of corridors round a block (x 1.8-12.2, y -0.6-0.6), mapped all round; the UAV ends
  // in the north corridor at x = 6.5, where the window has forgotten both ends of the block.
  // The path to the south corridor goes round one end. An obstacle remembered on that way (the
  // flight loop's BlockingObstacles: the window forgets what blocked a path there, and the same
  // path came back) keeps every later path its clearance away.
  test::BoxScene s = hall();
  addBox(s, 1.8, -0.6, 0.0, 12.2, 0.6, 2.7);    // the block
  const double z = 1.2;
  test::SceneFlight f(Vec3(6.5, -1.4, z));
  f.fly(s, Vec3(6.5, -1.4, z), Vec3(13.1, -1.4, z), 0.0);
  f.fly(s, Vec3(13.1, -1.4, z), Vec3(13.1, 1.4, z), 0.5 * kPi);
  f.fly(s, Vec3(13.1, 1.4, z), Vec3(0.9, 1.4, z), kPi);
  f.fly(s, Vec3(0.9, 1.4, z), Vec3(0.9, -1.4, z), -0.5 * kPi);
  f.fly(s, Vec3(0.9, -1.4, z), Vec3(0.9, 1.4, z), 0.5 * kPi);
  const Vec3 here(6.5, 1.4, z), goal(6.5, -1.4, z);
  f.fly(s, Vec3(0.9, 1.4, z), here, 0.0);
  ASSERT_EQ(f.grid.stateAt(Vec3(0.9, 0.0, z)), VoxelState::Unknown);   // the west end, forgotten
  ASSERT_EQ(f.grid.stateAt(Vec3(13.1, 0.0, z)), VoxelState::Unknown);  // the east end too

  FlightPathOptions opt;
  opt.clearance = 0.35;
  const auto first = planFlightPath(f.graph, f.grid, here, goal, opt);
  ASSERT_TRUE(first.has_value());
  // Where it passes the end of the block (y = 0).
  std::optional<Vec3> spot;
  for (size_t i = 1; i < first->size(); ++i) {
    const Vec3 &a = (*first)[i - 1], &b = (*first)[i];
    if (a.y() * b.y() <= 0.0 && std::abs(b.y() - a.y()) > 1e-9) spot = a + (b - a) * (-a.y() / (b.y() - a.y()));
  }
  ASSERT_TRUE(spot.has_value());
  ASSERT_EQ(f.grid.stateAt(*spot), VoxelState::Unknown);
  const bool west = spot->x() < 6.5;

  opt.avoid = {*spot};
  const auto second = planFlightPath(f.graph, f.grid, here, goal, opt);
  ASSERT_TRUE(second.has_value()) << "round the other end, or past the spot at more than the clearance";
  EXPECT_FALSE(polylinePassesNear(*second, opt.avoid, opt.clearance));
  for (size_t i = 1; i < second->size(); ++i) {
    const Vec3 &a = (*second)[i - 1], &b = (*second)[i];
    const int n = int(std::ceil((b - a).norm() / 0.05));
    for (int k = 0; k <= n; ++k) {
      const Vec3 q = a + (b - a) * (double(k) / n);
      if (!f.grid.inWindow(f.grid.keyOf(q))) continue;  // checked again when the window gets there
      ASSERT_GE(distanceToSolids(s, q), 0.25) << "at (" << q.transpose() << ")";
    }
  }
  std::printf("first round the %s end, passing (%.2f %.2f %.2f); then %zu points, %.1f m\n", west ? "west" : "east",
              spot->x(), spot->y(), spot->z(), second->size(), polylineLength(*second));

  // Obstacles remembered across both ends (walls of them at y = 0, x -0.2-1.8 and 12.2-14.0):
  // no path keeps clear of them, so the ladder flies past them (the map decides when the UAV
  // gets there) rather than shutting the UAV in; with the one spot, it keeps clear as above.
  const std::vector<double> clearances{0.35};
  const auto one = planFlightPathLadder(f.graph, f.grid, here, goal, opt, clearances);
  ASSERT_TRUE(one.has_value());
  EXPECT_FALSE(one->past_remembered);
  for (const double x0 : {-0.2, 12.2})
    for (double x = x0; x <= x0 + 2.0; x += 0.2)
      for (const double zz : {0.6, 0.9, 1.2, 1.5, 1.8}) opt.avoid.push_back(Vec3(x, 0.0, zz));
  EXPECT_FALSE(planFlightPath(f.graph, f.grid, here, goal, opt).has_value());
  const auto both = planFlightPathLadder(f.graph, f.grid, here, goal, opt, clearances);
  ASSERT_TRUE(both.has_value());
  EXPECT_TRUE(both->past_remembered);
  EXPECT_LT((both->path.back() - goal).norm(), 0.6);
}
