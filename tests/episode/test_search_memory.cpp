// TargetMemory, ObjectTries and BlockingObstacles: what the flight loop gives up on, for how long, and
// when for good, and where paths were found blocked.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/dense_grid.hpp"
#include "ussnav/episode/search_memory.hpp"

using namespace ussnav;

TEST(TargetMemory, AnUnreachableTargetIsSkippedForAWhileAndTheThirdTimeForGood) {
  TargetMemory m;
  const Vec3 a(1, 2, 1.2), near_a(1.5, 2.3, 1.2), b(4, 2, 1.2);
  EXPECT_FALSE(m.skipped(a, 0.0));
  EXPECT_EQ(m.skipUnreachable(a, 10.0, 20.0), 0);
  EXPECT_TRUE(m.skipped(a, 10.0));
  EXPECT_TRUE(m.skipped(near_a, 29.9));  // 0.58 m away: the same target
  EXPECT_FALSE(m.skipped(b, 10.0));
  EXPECT_FALSE(m.skipped(a, 30.0));      // tried again after 20 s
  EXPECT_TRUE(m.pendingRetry(29.9));
  EXPECT_FALSE(m.pendingRetry(30.0));
  EXPECT_EQ(m.skipUnreachable(near_a, 30.0, 20.0), 1);
  EXPECT_FALSE(m.skipped(a, 50.0));
  EXPECT_EQ(m.skipUnreachable(a, 50.0, 20.0), 2);
  EXPECT_TRUE(m.skipped(a, 1e9));         // the third time for good
  EXPECT_FALSE(m.pendingRetry(80.0));     // nothing left to wait for
}

TEST(TargetMemory, SkippedForGoodAndLookedFrom) {
  TargetMemory m;
  const Vec3 door(3, 0, 1.2), from(1, 0, 1.2);
  EXPECT_EQ(m.lookedFrom(door), nullptr);
  m.addLooked(door, from);
  ASSERT_NE(m.lookedFrom(door + Vec3(0.5, 0, 0)), nullptr);
  EXPECT_EQ(*m.lookedFrom(door), from);
  EXPECT_EQ(m.lookedFrom(door + Vec3(1.0, 0, 0)), nullptr);
  EXPECT_FALSE(m.skipped(door, 5.0));  // looked at once: not skipped
  m.skipForGood(door);
  EXPECT_TRUE(m.skipped(door, 1e9));
  EXPECT_FALSE(m.pendingRetry(5.0));
  EXPECT_EQ(m.size(), 1u);
}

TEST(ObjectTries, FailedApproachesDropAnObjectTheThirdTime) {
  ObjectTries o;
  EXPECT_FALSE(o.skipped(7, 0.0));
  o.fail(7, 10.0, 20.0);
  EXPECT_TRUE(o.skipped(7, 29.0));
  EXPECT_FALSE(o.skipped(8, 29.0));
  EXPECT_TRUE(o.pendingRetry(29.0));
  EXPECT_FALSE(o.skipped(7, 30.0));
  o.fail(7, 30.0, 20.0);
  EXPECT_FALSE(o.skipped(7, 50.0));
  o.fail(7, 50.0, 20.0);
  EXPECT_TRUE(o.skipped(7, 1e9));
  EXPECT_FALSE(o.pendingRetry(60.0));
}

TEST(ObjectTries, TransitsAreCountedAndABlockedOneIsRefundedAFewTimes) {
  ObjectTries o;
  for (int i = 0; i < ObjectTries::kMaxTransits; ++i) {
    EXPECT_TRUE(o.mayTransit(3));
    o.countTransit(3);
  }
  EXPECT_FALSE(o.mayTransit(3));
  for (int i = 0; i < ObjectTries::kMaxTransitReplans; ++i) {
    o.transitBlocked(3);  // no try of the object: one more transit
    EXPECT_TRUE(o.mayTransit(3)) << i;
    o.countTransit(3);
  }
  o.transitBlocked(3);  // one more than kMaxTransitReplans: not refunded
  EXPECT_FALSE(o.mayTransit(3));
}

TEST(ObjectTries, FailuresFromAfarCountOnlyAfterManyAndAllowOneMoreTransit) {
  ObjectTries o;
  o.countTransit(5);
  o.countTransit(5);
  ASSERT_FALSE(o.mayTransit(5));
  double t = 0.0;
  for (int i = 0; i < ObjectTries::kMaxFarTries; ++i, t += 30.0) {
    o.failFromAfar(5, t, 20.0, false);
    EXPECT_TRUE(o.skipped(5, t + 19.0));
    EXPECT_FALSE(o.skipped(5, t + 20.0));
    EXPECT_TRUE(o.mayTransit(5));  // one more transit allowed
    o.countTransit(5);
  }
  // The next failures from afar count as failed approaches: three of them drop it for good.
  for (int i = 0; i < ObjectTries::kMaxObjectTries; ++i, t += 30.0) o.failFromAfar(5, t, 20.0, false);
  EXPECT_TRUE(o.skipped(5, 1e9));
  // From near, a failure counts at once.
  o.failFromAfar(6, 0.0, 20.0, true);
  o.failFromAfar(6, 30.0, 20.0, true);
  EXPECT_FALSE(o.skipped(6, 60.0));
  o.failFromAfar(6, 60.0, 20.0, true);
  EXPECT_TRUE(o.skipped(6, 1e9));
}

TEST(ObjectTries, AWaitFromAfarEndsWhenTheUavComesNear) {
  ObjectTries o;
  o.failFromAfar(7, 0.0, 20.0, false, false, 3.0);
  EXPECT_TRUE(o.skipped(7, 5.0));        // no distance given: the whole wait
  EXPECT_TRUE(o.skipped(7, 5.0, 4.0));   // still beyond the radius
  EXPECT_FALSE(o.skipped(7, 5.0, 2.5));  // within it: the map around it is there now
  // Failing again from near is a failure, and waits the whole time whatever the distance.
  o.failFromAfar(7, 6.0, 20.0, true, false, 3.0);
  EXPECT_TRUE(o.skipped(7, 10.0, 0.5));
  EXPECT_FALSE(o.skipped(7, 26.0, 0.5));
  // Without a radius a wait from afar is the whole wait, as before.
  o.failFromAfar(8, 0.0, 20.0, false);
  EXPECT_TRUE(o.skipped(8, 5.0, 0.1));
}

TEST(ObjectTries, SpotsLookedFromInVainAreKeptPerObject) {
  ObjectTries o;
  EXPECT_FALSE(o.lookedInVainFrom(4, Vec3(1, 1, 1.2)));
  o.noViewFrom(4, Vec3(1, 1, 1.2));
  EXPECT_TRUE(o.lookedInVainFrom(4, Vec3(1.3, 1.2, 1.2)));   // 0.36 m away
  EXPECT_FALSE(o.lookedInVainFrom(4, Vec3(1.6, 1, 1.2)));    // 0.6 m away
  EXPECT_FALSE(o.lookedInVainFrom(5, Vec3(1, 1, 1.2)));      // another object
  EXPECT_TRUE(o.noPoseSpots(4).empty());
  o.noPoseFrom(4, Vec3(2, 2, 1.2));
  ASSERT_EQ(o.noPoseSpots(4).size(), 1u);
  EXPECT_TRUE(o.noPoseSpots(5).empty());
}

TEST(ObjectTries, AFailedSightingCountsNoFailure) {
  ObjectTries o;
  for (int i = 0; i < ObjectTries::kMaxObjectTries + 1; ++i) o.fail(9, 10.0 * i, 20.0, true);
  EXPECT_FALSE(o.skipped(9, 1.0));  // no retry wait, never dropped
  EXPECT_TRUE(o.sightingChecked(9));
  o.failFromAfar(10, 0.0, 20.0, true, true);
  EXPECT_FALSE(o.skipped(10, 1.0));
  EXPECT_TRUE(o.sightingChecked(10));
  EXPECT_FALSE(o.sightingChecked(11));
}

TEST(BlockingObstacles, TheVoxelsThatBlockedAPathAreKeptAndGivenBackOnceForgotten) {
  // A wall x 2.0-2.2 (occupied voxels), free space in front of it, nothing known beyond x 3.
  test::DenseGrid map(Aabb::of(Vec3(0, 0, 0), Vec3(4, 2, 2.4)), 0.1);
  map.fill(Aabb::of(Vec3(0, 0, 0), Vec3(2, 2, 2.4)), VoxelState::Free);
  map.fill(Aabb::of(Vec3(2.0, 0, 0), Vec3(2.2, 2, 2.4)), VoxelState::Occupied);
  BlockingObstacles b;
  // A path blocked at (1.65, 1.0, 1.2) by a 0.35 m margin: the wall voxels whose box comes
  // within 0.35 + 0.087 m of it. The nearest face is at x = 2.0 (0.35 m away): the voxels of the
  // first layer (x 2.0-2.1) with |dy|, |dz| small enough, none of the second (0.45 m away).
  const double r = 0.35 + 0.5 * std::sqrt(3.0) * 0.1;
  const int added = b.add(map, Vec3(1.65, 1.0, 1.2), r);
  int expected = 0;
  for (int y = 0; y < 20; ++y)
    for (int z = 0; z < 24; ++z) {
      const double dy = std::max({0.0, 0.1 * y - 1.0, 1.0 - 0.1 * (y + 1)});
      const double dz = std::max({0.0, 0.1 * z - 1.2, 1.2 - 0.1 * (z + 1)});
      expected += std::sqrt(0.35 * 0.35 + dy * dy + dz * dz) <= r;
    }
  EXPECT_EQ(added, expected);
  EXPECT_GT(added, 4);
  EXPECT_EQ(b.add(map, Vec3(1.65, 1.0, 1.2), r), 0);  // kept once
  EXPECT_EQ(b.size(), size_t(added));
  EXPECT_TRUE(b.forgotten(map).empty());  // the map still holds them
  // The window moves on: the wall is forgotten, and every kept voxel comes back, as a centre.
  map.setWindow(Aabb::of(Vec3(0, 0, 0), Vec3(1.5, 2, 2.4)));
  const std::vector<Vec3> f = b.forgotten(map);
  ASSERT_EQ(f.size(), size_t(added));
  for (const Vec3& c : f) EXPECT_NEAR(c.x(), 2.05, 1e-9);
  // At most kMax, the oldest dropped first.
  test::DenseGrid big(Aabb::of(Vec3(0, 0, 0), Vec3(8, 8, 2.4)), 0.1, VoxelState::Occupied);
  int more = 0;
  for (int i = 0; i < 100; ++i) more += b.add(big, Vec3(0.5 + 0.7 * (i % 10), 0.5 + 0.7 * (i / 10), 1.2), 0.3);
  ASSERT_GT(size_t(more), BlockingObstacles::kMax);
  EXPECT_EQ(b.size(), BlockingObstacles::kMax);
  map.resetWindow();
  EXPECT_EQ(b.add(map, Vec3(1.65, 1.0, 1.2), r), added);  // the first ones went first: new again
}
