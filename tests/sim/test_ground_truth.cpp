#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/sim/gt_paths.hpp"

using namespace ussnav;

TEST(GroundTruth, WallsOccupiedDoorOpeningFreeObjectsLabelled) {
  World w = test::twoRooms(true);
  const int bed = test::addObject(w, "bed", Vec3(2.0, 2.0, 0.3), Vec3(1.0, 0.8, 0.3));
  GroundTruthGrid gt(w, 0.05);
  EXPECT_TRUE(gt.occupiedAt(Vec3(5.0, 0.5, 1.0)));    // middle wall, beside the door
  EXPECT_FALSE(gt.occupiedAt(Vec3(5.0, 2.0, 1.0)));   // door opening
  EXPECT_TRUE(gt.occupiedAt(Vec3(5.0, 2.0, 2.5)));    // lintel above the door
  EXPECT_TRUE(gt.occupiedAt(Vec3(0.0, 2.0, 1.0)));    // outer wall
  EXPECT_TRUE(gt.occupiedAt(Vec3(2.5, 2.0, -0.05)));  // floor slab
  EXPECT_TRUE(gt.occupiedAt(Vec3(2.5, 2.0, 2.85)));   // ceiling slab
  EXPECT_FALSE(gt.occupiedAt(Vec3(2.5, 3.5, 1.2)));   // free air
  EXPECT_EQ(gt.instanceOfLabel(gt.labelAt(Vec3(2.0, 2.0, 0.3))), bed);
  EXPECT_EQ(gt.instanceOfLabel(gt.labelAt(Vec3(5.0, 0.5, 1.0))), 0);
  EXPECT_EQ(gt.state(gt.keyOf(Vec3(100, 0, 0))), VoxelState::Unknown);
}

// The Webots apartment's kitchen door: a 1 m wall piece with a 0.9 m opening between two
// collinear walls 0.3 m thick. Their end caps (half the thickness past each end, so corners
// close) must not narrow the door: it stays 0.9 m wide, the walls beside it stay solid.
TEST(GroundTruth, NeighbouringWallsDoNotNarrowADoor) {
  World w;
  auto wall = [&](double y0, double y1, std::vector<Opening> openings) {
    Wall wl;
    wl.a = Vec2(0.0, y0);
    wl.b = Vec2(0.0, y1);
    wl.thickness = 0.3;
    wl.z0 = 0.0;
    wl.z1 = 2.4;
    wl.openings = std::move(openings);
    w.walls.push_back(wl);
  };
  Opening door;
  door.start = 0.05, door.end = 0.95, door.bottom = 0.0, door.top = 1.95;
  wall(0.0, 1.0, {door});   // opening y in [0.05, 0.95]
  wall(-3.0, 0.0, {});      // its cap would reach y = 0.15
  wall(1.0, 4.0, {});       // its cap would reach y = 0.85
  w.has_floor = false;
  GroundTruthGrid gt(w, 0.05);
  int free = 0;
  for (double y = -0.5; y <= 1.5; y += 0.05)
    if (!gt.occupiedAt(Vec3(0.0, y + 0.025, 1.2))) ++free;
  EXPECT_EQ(free, 18);                              // 0.9 m of 5 cm cells
  EXPECT_FALSE(gt.occupiedAt(Vec3(0.1, 0.1, 1.2)));   // inside the door, in the neighbour's cap
  EXPECT_FALSE(gt.occupiedAt(Vec3(-0.1, 0.9, 1.2)));
  EXPECT_TRUE(gt.occupiedAt(Vec3(0.0, -0.05, 1.2)));  // the walls beside it
  EXPECT_TRUE(gt.occupiedAt(Vec3(0.0, 1.05, 1.2)));
  EXPECT_TRUE(gt.occupiedAt(Vec3(0.0, 0.5, 2.1)));    // the lintel
}

TEST(GroundTruth, RaycastEqualsAnalyticDistance) {
  World w = test::boxRoom(6, 4);
  GroundTruthGrid gt(w, 0.05);
  // Inner face of the wall at x = 6 is at x = 5.95.
  const Vec3 o(2.0, 2.0, 1.2);
  for (double ang : {0.0, 0.3, -0.3}) {
    const Vec3 d(std::cos(ang), std::sin(ang), 0.0);
    const auto h = gt.raycast(o, d, 10.0);
    ASSERT_TRUE(h.hit);
    const double expect = (5.95 - o.x()) / d.x();
    EXPECT_NEAR(h.range, expect, 0.05 / std::cos(ang) + 1e-9) << ang;
  }
  EXPECT_FALSE(gt.raycast(o, Vec3(1, 0, 0), 3.0).hit);  // beyond max range
}

TEST(GtPaths, EmptyRoomIsNearlyEuclidean) {
  World w = test::boxRoom(6, 4);
  GroundTruthGrid gt(w, 0.05);
  GtPlanner p(gt, w, 1.2, 0.25);
  auto path = p.shortestPath(Vec2(1.0, 1.0), Vec2(5.0, 3.0));
  ASSERT_TRUE(path);
  const double euclid = (Vec2(5, 3) - Vec2(1, 1)).norm();
  EXPECT_NEAR(GtPlanner::length(*path), euclid, 0.02 * euclid + 0.1);
  EXPECT_FALSE(p.freeAt(Vec2(0.1, 2.0)));  // within the radius of the wall
}

TEST(GtPaths, PathGoesThroughTheDoor) {
  World w = test::twoRooms(true);
  GroundTruthGrid gt(w, 0.05);
  GtPlanner p(gt, w, 1.2, 0.25);
  auto path = p.shortestPath(Vec2(2.5, 0.6), Vec2(7.5, 0.6));
  ASSERT_TRUE(path);
  EXPECT_GT(GtPlanner::length(*path), 5.0 + 0.5);  // longer than the straight line
  bool through_door = false;
  for (size_t i = 1; i < path->size(); ++i) {
    const Vec3 a = (*path)[i - 1], b = (*path)[i];
    if ((a.x() - 5.0) * (b.x() - 5.0) <= 0) {
      const double t = (5.0 - a.x()) / (b.x() - a.x());
      const double y = a.y() + t * (b.y() - a.y());
      through_door = y > 1.5 && y < 2.5;
    }
  }
  EXPECT_TRUE(through_door);
  for (const auto& q : *path) EXPECT_FALSE(gt.sphereCollides(q, 0.2));
  EXPECT_TRUE(p.allRoomsConnected(w));
}

TEST(GtPaths, RoomsWithoutDoorAreUnreachable) {
  World w = test::twoRooms(false);
  GroundTruthGrid gt(w, 0.05);
  GtPlanner p(gt, w, 1.2, 0.25);
  EXPECT_FALSE(p.shortestPath(Vec2(2.5, 2.0), Vec2(7.5, 2.0)).has_value());
  EXPECT_FALSE(p.allRoomsConnected(w));
}

TEST(GroundTruth, BlockSkippingRaycastAgreesWithPlainDda) {
  World w = test::twoRooms(true);
  test::addObject(w, "table", Vec3(2.0, 2.0, 0.4), Vec3(0.6, 0.4, 0.4), 0.3);
  GroundTruthGrid gt(w, 0.05);
  Rng rng(5);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 o(rng.uniform(0.3, 9.7), rng.uniform(0.3, 3.7), rng.uniform(0.2, 2.6));
    if (gt.occupiedAt(o)) continue;
    Vec3 d(rng.normal(), rng.normal(), rng.normal());
    d.normalize();
    const auto fast = gt.raycast(o, d, 8.0);
    const RayHit plain = castRay(gt, o, o + d * 8.0, false);
    ASSERT_EQ(fast.hit, plain.blocked) << i;
    if (fast.hit) {
      ++hits;
      EXPECT_NEAR(fast.range, plain.distance, 1e-6) << i;
    }
  }
  EXPECT_GT(hits, 2000);
}
