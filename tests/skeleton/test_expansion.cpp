#include <gtest/gtest.h>

#include <cmath>

#include "support/skeleton_scenes.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"
#include "ussnav/skeleton/expansion.hpp"
#include "ussnav/skeleton/sphere_sampler.hpp"

using namespace ussnav;
using namespace ussnav::test;

namespace {
BoundarySurface handSurface(const Vec3& nexus, const Vec3& normal) {
  BoundarySurface s;
  s.nexus = nexus;
  s.center = nexus;
  s.normal = normal.normalized();
  return s;
}
}  // namespace

TEST(ExpandNewPolyhedron, BoxRoomVerticesAreFreeOrOnSurfaces) {
  const BoxRoomScene scene = boxRoomGrid(Vec3(4.0, 4.0, 2.6));
  const SkeletonConfig cfg;
  const Vec3 seed(2.0, 2.0, 1.2);
  const Polyhedron p = expandNewPolyhedron(scene.grid, seed, fibonacciSphere(cfg.sphere_samples), cfg);
  ASSERT_TRUE(p.valid());
  ASSERT_EQ(p.points.size(), size_t(cfg.sphere_samples));
  int free = 0, obstacle = 0;
  for (size_t i = 0; i < p.points.size(); ++i) {
    const Vec3& q = p.points[i];
    const double r = (q - seed).norm();
    if (p.kinds[i] == VertexKind::Free) {
      ++free;
      EXPECT_NEAR(r, cfg.max_radius, 1e-9);
      EXPECT_EQ(scene.grid.stateAt(q), VoxelState::Free);
    } else {
      ++obstacle;
      EXPECT_EQ(p.kinds[i], VertexKind::Obstacle);  // the room is fully known
      EXPECT_LT(r, cfg.max_radius);
      // Walls are 2 m away, the floor 1.2 m, the ceiling 1.4 m: only floor and ceiling are hit.
      EXPECT_TRUE(std::abs(q.z()) < 1e-9 || std::abs(q.z() - 2.6) < 1e-9) << q.transpose();
    }
  }
  EXPECT_GT(free, 10);
  EXPECT_GE(obstacle, 3);  // the floor and ceiling caps
  EXPECT_TRUE(p.contains(seed));
  EXPECT_TRUE(scene.room.contains(p.centroid));
  Aabb room = scene.room;
  room.min -= Vec3::Constant(1e-9);
  room.max += Vec3::Constant(1e-9);
  for (int v : p.hullVertices()) EXPECT_TRUE(room.contains(p.points[size_t(v)])) << p.points[size_t(v)].transpose();
  // Nearly a ball of 1.4 m cut by the floor: between the cut ball and the inscribed 50-gon.
  EXPECT_GT(p.volume, 6.0);
  EXPECT_LT(p.volume, 4.0 / 3.0 * kPi * std::pow(cfg.max_radius, 3));
}

TEST(ExpandNewPolyhedron, UnknownSpaceIsContactOnlyWhenConfigured) {
  BoxRoomScene scene = boxRoomGrid(Vec3(4.0, 4.0, 2.6));
  scene.grid.hide(Aabb::of(Vec3(2.6, 0, 0), Vec3(4.0, 4.0, 2.6)));  // x > 2.6 not observed yet
  SkeletonConfig cfg;
  const Vec3 seed(2.0, 2.0, 1.2);
  const auto dirs = fibonacciSphere(cfg.sphere_samples);
  const Polyhedron contact = expandNewPolyhedron(scene.grid, seed, dirs, cfg);
  int unknown = 0;
  for (size_t i = 0; i < contact.points.size(); ++i) {
    if (contact.kinds[i] != VertexKind::Unknown) continue;
    ++unknown;
    EXPECT_NEAR(contact.points[i].x(), 2.6, 1e-9);  // stopped on the first unknown voxel
  }
  EXPECT_GT(unknown, 5);
  EXPECT_LE(contact.bounds.max.x(), 2.6 + 1e-9);

  cfg.unknown_is_contact = false;
  const Polyhedron through = expandNewPolyhedron(scene.grid, seed, dirs, cfg);
  for (VertexKind k : through.kinds) EXPECT_NE(k, VertexKind::Unknown);
  EXPECT_NEAR(through.bounds.max.x(), 2.0 + cfg.max_radius, 0.1);

  // ... but never beyond the edge of the map window.
  scene.grid.setWindow(Aabb::of(Vec3(-1, -1, -1), Vec3(2.5, 5, 4)));
  const Polyhedron clipped = expandNewPolyhedron(scene.grid, seed, dirs, cfg);
  EXPECT_LE(clipped.bounds.max.x(), 2.5 + 1e-9);
  int clipped_unknown = 0;
  for (VertexKind k : clipped.kinds) clipped_unknown += k == VertexKind::Unknown;
  EXPECT_GT(clipped_unknown, 5);
}

TEST(FindNewExpandSeed, ExtendsHalfTheFreeRunAlongTheNormal) {
  const CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  const SkeletonConfig cfg;
  const ConnectivityGraph empty(cfg);
  // Open corridor ahead: the run is max_extension long, the seed sits in its middle.
  SeedDecision d = findNewExpandSeed(handSurface(Vec3(1.0, 0.6, 1.2), Vec3::UnitX()), scene.grid, empty, cfg);
  EXPECT_EQ(d.status, SeedStatus::Accepted);
  EXPECT_TRUE(d.position.isApprox(Vec3(1.0 + 0.5 * cfg.max_extension, 0.6, 1.2), 1e-9)) << d.position.transpose();
  // The end wall at x = 10 cuts the run to 0.8 m.
  d = findNewExpandSeed(handSurface(Vec3(9.2, 0.6, 1.2), Vec3::UnitX()), scene.grid, empty, cfg);
  EXPECT_EQ(d.status, SeedStatus::Accepted);
  EXPECT_NEAR(d.position.x(), 9.6, 1e-9);
}

TEST(FindNewExpandSeed, RejectsUnsafeAndDefersUnknown) {
  CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  const SkeletonConfig cfg;
  const ConnectivityGraph empty(cfg);
  // Along the side wall, 0.15 m from it: closer than the robot radius.
  SeedDecision d = findNewExpandSeed(handSurface(Vec3(1.0, 0.15, 1.2), Vec3::UnitX()), scene.grid, empty, cfg);
  EXPECT_EQ(d.status, SeedStatus::Unsafe);
  // Straight into the wall 0.2 m away: the seed would be 0.1 m from it.
  d = findNewExpandSeed(handSurface(Vec3(1.0, 0.2, 1.2), -Vec3::UnitY()), scene.grid, empty, cfg);
  EXPECT_EQ(d.status, SeedStatus::Unsafe);
  // Unknown space 0.3 m ahead: the seed would touch it; wait for it to be observed.
  scene.grid.hide(Aabb::of(Vec3(1.3, 0, 0), Vec3(10, 1.2, 2.4)));
  d = findNewExpandSeed(handSurface(Vec3(1.0, 0.6, 1.2), Vec3::UnitX()), scene.grid, empty, cfg);
  ASSERT_EQ(d.status, SeedStatus::Deferred);
  EXPECT_EQ(scene.grid.state(d.probe), VoxelState::Unknown);
  EXPECT_NEAR(scene.grid.centerOf(d.probe).x(), 1.35, 1e-9);
  // Once observed, the same surface gives a seed.
  scene.grid.carve(Aabb::of(Vec3(1.3, 0, 0), Vec3(10, 1.2, 2.4)));
  EXPECT_EQ(findNewExpandSeed(handSurface(Vec3(1.0, 0.6, 1.2), Vec3::UnitX()), scene.grid, empty, cfg).status,
            SeedStatus::Accepted);
  // Outside the window: deferred too.
  scene.grid.setWindow(Aabb::of(Vec3(-1, -1, -1), Vec3(1.5, 2, 3)));
  d = findNewExpandSeed(handSurface(Vec3(1.0, 0.6, 1.2), Vec3::UnitX()), scene.grid, empty, cfg);
  EXPECT_EQ(d.status, SeedStatus::Deferred);
  EXPECT_FALSE(scene.grid.inWindow(d.probe));
}

TEST(FindNewExpandSeed, DropsSeedsInCoveredSpace) {
  const CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  SkeletonConfig cfg;
  cfg.max_expansions_per_frame = 1;  // only the polyhedron at the UAV
  ConnectivityGraph g(cfg);
  g.update(scene.grid, Vec3(3.0, 0.6, 1.2), 0.0);
  ASSERT_EQ(g.size(), 1u);
  const Vec3 c = g.node(0).center;
  // A surface whose seed lands on the first node's centre, and one inside its polyhedron.
  SeedDecision d = findNewExpandSeed(handSurface(c - Vec3(1.0, 0, 0), Vec3::UnitX()), scene.grid, g, cfg);
  EXPECT_EQ(d.status, SeedStatus::TooClose);
  const Polyhedron& p = g.node(0).polyhedron;
  ASSERT_TRUE(p.contains(c + Vec3(1.1, 0, 0)));
  ASSERT_FALSE(g.hasCenterWithin(c + Vec3(1.1, 0, 0), cfg.min_center_distance));
  d = findNewExpandSeed(handSurface(c + Vec3(0.1, 0, 0.0), Vec3::UnitX()), scene.grid, g, cfg);
  // The run from c + 0.1 along x ends 2 m on, its middle (c + 1.1) is inside node 0.
  EXPECT_EQ(d.status, SeedStatus::InsideExisting);
}

TEST(FindUnsafeVoxel, ReportsObstacleBeforeUnknown) {
  CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  scene.grid.hide(Aabb::of(Vec3(2.1, 0, 0), Vec3(3, 1.2, 2.4)));
  Vec3i k;
  VoxelState s;
  EXPECT_FALSE(findUnsafeVoxel(scene.grid, Vec3(1.0, 0.6, 1.2), 0.25, true, &k, &s));
  EXPECT_TRUE(findUnsafeVoxel(scene.grid, Vec3(2.0, 0.6, 1.2), 0.25, true, &k, &s));
  EXPECT_EQ(s, VoxelState::Unknown);
  EXPECT_FALSE(findUnsafeVoxel(scene.grid, Vec3(2.0, 0.6, 1.2), 0.25, false, &k, &s));
  EXPECT_TRUE(findUnsafeVoxel(scene.grid, Vec3(2.0, 0.2, 1.2), 0.25, true, &k, &s));
  EXPECT_EQ(s, VoxelState::Occupied);  // the wall wins over the unknown voxels
}

TEST(CastRayThroughGaps, PassesSensorHolesButNotUnexploredSpace) {
  CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  const Vec3 a(0.55, 0.65, 1.25), b(5.55, 0.65, 1.25);
  // One unknown voxel on the way (a hole) is passed when up to 0.2 m gaps are tolerated.
  scene.grid.set(scene.grid.keyOf(Vec3(2.05, 0.65, 1.25)), VoxelState::Unknown);
  RayHit h = castRayThroughGaps(scene.grid, a, b, true, 0.2);
  EXPECT_FALSE(h.blocked);
  h = castRayThroughGaps(scene.grid, a, b, true, 0.0);
  ASSERT_TRUE(h.blocked);
  EXPECT_EQ(h.hit_state, VoxelState::Unknown);
  EXPECT_NEAR(h.point.x(), 2.0, 1e-9);
  // Three unknown voxels in a row (0.3 m) are unexplored space: stop where they begin.
  scene.grid.hide(Aabb::of(Vec3(3.0, 0, 0), Vec3(3.3, 1.2, 2.4)));
  h = castRayThroughGaps(scene.grid, a, b, true, 0.2);
  ASSERT_TRUE(h.blocked);
  EXPECT_NEAR(h.point.x(), 3.0, 1e-9);
  // Unknown up to the end of the segment is not a hole either.
  h = castRayThroughGaps(scene.grid, a, Vec3(3.15, 0.65, 1.25), true, 0.2);
  ASSERT_TRUE(h.blocked);
  EXPECT_NEAR(h.point.x(), 3.0, 1e-9);
  // Unknown passable: only obstacles and the window edge stop the ray.
  EXPECT_FALSE(castRayThroughGaps(scene.grid, a, b, false, 0.0).blocked);
  h = castRayThroughGaps(scene.grid, a, Vec3(12.0, 0.65, 1.25), false, 0.0);
  ASSERT_TRUE(h.blocked);
  EXPECT_EQ(h.hit_state, VoxelState::Occupied);
  EXPECT_NEAR(h.point.x(), 10.0, 1e-9);
  scene.grid.setWindow(Aabb::of(Vec3(-1, -1, -1), Vec3(4.5, 2, 3)));
  h = castRayThroughGaps(scene.grid, a, b, false, 0.0);
  ASSERT_TRUE(h.blocked);
  EXPECT_EQ(h.hit_state, VoxelState::Unknown);
  EXPECT_NEAR(h.point.x(), 4.5, 1e-9);
}

TEST(FindUnsafeVoxel, ToleratesAFewUnknownVoxels) {
  CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  const Vec3 p(2.05, 0.65, 1.25);
  scene.grid.set(scene.grid.keyOf(p + Vec3(0.1, 0, 0)), VoxelState::Unknown);
  scene.grid.set(scene.grid.keyOf(p + Vec3(0, 0.1, 0)), VoxelState::Unknown);
  EXPECT_TRUE(findUnsafeVoxel(scene.grid, p, 0.25, true, nullptr, nullptr, 0));
  EXPECT_TRUE(findUnsafeVoxel(scene.grid, p, 0.25, true, nullptr, nullptr, 1));
  EXPECT_FALSE(findUnsafeVoxel(scene.grid, p, 0.25, true, nullptr, nullptr, 2));
}

TEST(ExpandNewPolyhedron, RefinementRaysFillTheCornerBetweenTwoWalls) {
  // A seed 0.6 m from two walls of a room corner: the 50 rays cut the corner; refinement rays
  // through the contact faces push the hull into it. The refined hull contains the base hull,
  // covers more of the room's free voxels, and every vertex it adds is a ray end point in the
  // room (free at max_radius, or on a wall, the floor or the ceiling).
  const BoxRoomScene scene = boxRoomGrid(Vec3(4.0, 4.0, 2.6));
  SkeletonConfig cfg;
  const Vec3 seed(0.6, 0.6, 1.2);
  const auto dirs = fibonacciSphere(cfg.sphere_samples);
  const Polyhedron base = expandNewPolyhedron(scene.grid, seed, dirs, cfg);
  cfg.refine_rays = 50;
  const Polyhedron refined = expandNewPolyhedron(scene.grid, seed, dirs, cfg);
  ASSERT_TRUE(base.valid());
  ASSERT_TRUE(refined.valid());
  ASSERT_GT(refined.points.size(), base.points.size());
  EXPECT_LE(refined.points.size(), base.points.size() + 50);
  for (int v : base.hullVertices()) EXPECT_TRUE(refined.contains(base.points[size_t(v)], 1e-6));
  Aabb room = scene.room;
  room.min -= Vec3::Constant(1e-9);
  room.max += Vec3::Constant(1e-9);
  for (size_t i = base.points.size(); i < refined.points.size(); ++i) {
    const Vec3& q = refined.points[i];
    EXPECT_TRUE(room.contains(q)) << q.transpose();
    EXPECT_LE((q - seed).norm(), cfg.max_radius + 1e-9);
    // A refinement point lies at least refine_min_gain outside the hull it refined.
    EXPECT_FALSE(base.contains(q, cfg.refine_min_gain - 1e-6)) << q.transpose();
  }
  int in_base = 0, in_refined = 0;
  for (double x = 0.05; x < 2.0; x += 0.1)
    for (double y = 0.05; y < 2.0; y += 0.1)
      for (double z = 0.75; z < 1.7; z += 0.1) {
        in_base += base.contains(Vec3(x, y, z));
        in_refined += refined.contains(Vec3(x, y, z));
      }
  EXPECT_GT(in_refined, in_base + in_base / 100);  // more of the corner (3188 -> 3232 samples)
  EXPECT_GT(refined.volume, base.volume);
}
