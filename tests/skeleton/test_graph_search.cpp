#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "support/skeleton_scenes.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"
#include "ussnav/skeleton/graph_search.hpp"
#include "ussnav/skeleton/grid_path.hpp"

using namespace ussnav;
using namespace ussnav::test;

namespace {


void grow(ConnectivityGraph& g, const OccupancyMap& map, const Vec3& uav) {
  for (int f = 0; f < 50; ++f)
    if (g.update(map, uav, 0.1 * f).expansions == 0 && g.queuedSurfaces() == 0) return;
}

// Every segment is free of obstacles and unknown space, sampled finely as well as by castRay.
void expectClearPolyline(const OccupancyMap& map, const std::vector<Vec3>& pts) {
  ASSERT_GE(pts.size(), 2u);
  EXPECT_TRUE(polylineClear(map, pts, true));
  for (size_t i = 1; i < pts.size(); ++i)
    for (int k = 0; k <= 100; ++k) {
      const Vec3 p = pts[i - 1] + (pts[i] - pts[i - 1]) * (k / 100.0);
      EXPECT_EQ(map.stateAt(p), VoxelState::Free) << "segment " << i << " at " << p.transpose();
    }
}

}  // namespace

TEST(GraphSearch, PathBetweenRoomsGoesThroughTheDoor) {
  const TwoRoomsScene scene = twoRoomsGrid();
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(1.0, 1.0, 1.2));
  const Vec3 start(0.8, 0.7, 1.0), goal(7.5, 0.6, 1.5);
  ASSERT_FALSE(lineOfSight(scene.grid, start, goal, false));
  const GraphPath path = findGraphPath(g, scene.grid, start, goal);
  ASSERT_TRUE(path.found);
  EXPECT_EQ(path.points.front(), start);
  EXPECT_EQ(path.points.back(), goal);
  EXPECT_FALSE(path.nodes.empty());
  expectClearPolyline(scene.grid, path.points);
  // The one crossing of the wall slab is in the door.
  Aabb door = scene.door;
  door.min -= Vec3::Constant(1e-6);
  door.max += Vec3::Constant(1e-6);
  bool crossed = false;
  for (size_t i = 1; i < path.points.size(); ++i)
    for (int k = 0; k <= 200; ++k) {
      const Vec3 p = path.points[i - 1] + (path.points[i] - path.points[i - 1]) * (k / 200.0);
      if (p.x() > scene.wall_min_x && p.x() < scene.wall_max_x) {
        crossed = true;
        EXPECT_TRUE(door.contains(p)) << p.transpose();
      }
    }
  EXPECT_TRUE(crossed);
  // Shortcut: not much longer than going straight to the door and on to the goal.
  const Vec3 door_mid = scene.door.center();
  const double lower = (door_mid - start).norm() + (goal - door_mid).norm();
  EXPECT_GE(path.length, (goal - start).norm());
  EXPECT_LE(path.length, 1.25 * lower);
  EXPECT_NEAR(path.length, polylineLength(path.points), 1e-9);
}

TEST(GraphSearch, DirectLineOfSightNeedsNoGraph) {
  const BoxRoomScene scene = boxRoomGrid();
  const ConnectivityGraph empty;
  const GraphPath path = findGraphPath(empty, scene.grid, Vec3(0.5, 0.5, 1.0), Vec3(3.5, 3.0, 1.8));
  ASSERT_TRUE(path.found);
  EXPECT_EQ(path.points.size(), 2u);
  EXPECT_TRUE(path.nodes.empty());
}

TEST(GraphSearch, SealedRoomIsUnreachable) {
  TwoRoomsScene scene = twoRoomsGrid();
  scene.grid.wall(scene.door);  // no door
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(1.0, 1.0, 1.2));
  grow(g, scene.grid, Vec3(6.0, 2.0, 1.2));  // the UAV is put into room B: a second component
  ASSERT_GT(g.size(), 4u);
  EXPECT_FALSE(findGraphPath(g, scene.grid, Vec3(1.0, 1.0, 1.2), Vec3(6.0, 2.0, 1.2)).found);
  // Within each room paths exist.
  EXPECT_TRUE(findGraphPath(g, scene.grid, Vec3(0.5, 0.5, 1.2), Vec3(3.5, 3.5, 0.6)).found);
  EXPECT_TRUE(findGraphPath(g, scene.grid, Vec3(4.8, 0.5, 1.2), Vec3(7.6, 3.6, 2.0)).found);
}

TEST(GraphSearch, AvoidsEdgesThatTheCurrentMapBlocks) {
  CorridorScene scene = corridorGrid(10.0, 1.2, 2.4);
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(0.6, 0.6, 1.2));
  const Vec3 start(0.6, 0.6, 1.2), goal(9.4, 0.6, 1.2);
  ASSERT_TRUE(findGraphPath(g, scene.grid, start, goal).found);
  // Something now closes the corridor in the middle: the graph still has its edges there, but
  // the search re-checks them against the current map.
  scene.grid.wall(Aabb::of(Vec3(4.9, 0, 0), Vec3(5.1, 1.2, 2.4)));
  EXPECT_FALSE(findGraphPath(g, scene.grid, start, goal).found);
  // A path on one side is unaffected.
  const GraphPath near = findGraphPath(g, scene.grid, start, Vec3(4.5, 0.3, 0.5));
  ASSERT_TRUE(near.found);
  expectClearPolyline(scene.grid, near.points);
}

TEST(GraphSearch, ShortcutsAroundAnL) {
  // An L-shaped pair of corridors: the path turns once and stays clear.
  DenseGrid grid(Aabb::of(Vec3(-0.2, -0.2, -0.2), Vec3(6.2, 6.2, 2.6)), 0.1, VoxelState::Occupied);
  grid.carve(Aabb::of(Vec3(0, 0, 0), Vec3(6.0, 1.4, 2.4)));
  grid.carve(Aabb::of(Vec3(4.6, 0, 0), Vec3(6.0, 6.0, 2.4)));
  ConnectivityGraph g;
  grow(g, grid, Vec3(0.7, 0.7, 1.2));
  const GraphPath path = findGraphPath(g, grid, Vec3(0.5, 0.7, 1.2), Vec3(5.3, 5.5, 1.2));
  ASSERT_TRUE(path.found);
  expectClearPolyline(grid, path.points);
  // One bend is enough after shortcutting; the raw node chain has more points.
  EXPECT_LE(path.points.size(), 4u);
  EXPECT_LE(path.length, 1.2 * ((Vec3(5.3, 0.7, 1.2) - Vec3(0.5, 0.7, 1.2)).norm() + 4.8));
  EXPECT_THROW(findGraphPath(g, grid, Vec3(std::nan(""), 0, 0), Vec3::Zero()), InputError);
}

TEST(GridPath, FindsShortPathsAroundWallsOnly) {
  const TwoRoomsScene scene = twoRoomsGrid();
  const Vec3 a(3.6, 1.2, 1.0), b(4.6, 1.2, 1.0);  // either side of the wall, near the door
  ASSERT_FALSE(lineOfSight(scene.grid, a, b, true));
  const auto path = gridPath(scene.grid, a, b, 3.0);
  ASSERT_TRUE(path.has_value());
  EXPECT_EQ(path->front(), a);
  EXPECT_EQ(path->back(), b);
  EXPECT_TRUE(polylineClear(scene.grid, *path, true));
  EXPECT_LE(polylineLength(*path), 3.0);
  EXPECT_GE(polylineLength(*path), (b - a).norm());
  // Too short a budget, or far from the door: nothing.
  EXPECT_FALSE(gridPath(scene.grid, a, b, (b - a).norm() + 0.01).has_value());
  EXPECT_FALSE(gridPath(scene.grid, Vec3(3.0, 0.3, 1.0), Vec3(5.2, 0.3, 1.0), 3.0).has_value());
  // A longer budget reaches around from farther away.
  EXPECT_TRUE(gridPath(scene.grid, Vec3(3.0, 0.3, 1.0), Vec3(5.2, 0.3, 1.0), 5.0).has_value());
}

TEST(GridPath, CoarseCellsSkipSlitsTooNarrowToFly) {
  // A wall with a 0.2 m slit: passable voxel by voxel, not on 0.2 m cells.
  DenseGrid grid(Aabb::of(Vec3(-0.2, -0.2, -0.2), Vec3(4.2, 3.2, 2.6)), 0.1, VoxelState::Occupied);
  grid.carve(Aabb::of(Vec3(0, 0, 0), Vec3(4.0, 3.0, 2.4)));
  grid.wall(Aabb::of(Vec3(1.9, 0, 0), Vec3(2.1, 3.0, 2.4)));
  grid.carve(Aabb::of(Vec3(1.9, 1.3, 0.8), Vec3(2.1, 1.5, 1.6)));  // voxels 13-14: no 2-cell fits
  const Vec3 a(1.5, 1.4, 1.2), b(2.5, 1.4, 1.2);
  const auto fine = gridPath(grid, a, b, 2.0, true, 1);
  ASSERT_TRUE(fine.has_value());
  EXPECT_TRUE(polylineClear(grid, *fine, true));
  EXPECT_FALSE(gridPath(grid, a, b, 2.0, true, 2).has_value());
  // Widen it to 0.6 m: coarse cells pass too, and the result is clear voxel by voxel.
  grid.carve(Aabb::of(Vec3(1.9, 1.2, 0.8), Vec3(2.1, 1.8, 1.6)));
  const auto coarse = gridPath(grid, a, b, 2.0, true, 2);
  ASSERT_TRUE(coarse.has_value());
  EXPECT_TRUE(polylineClear(grid, *coarse, true));
  EXPECT_LE(polylineLength(*coarse), 2.0);
}

TEST(GridPath, TubeOfSightKeepsClearOfCorners) {
  BoxRoomScene scene = boxRoomGrid();
  // One occupied voxel [2.0, 2.1]^2 x [1.0, 1.1]; a segment passing 0.03 m beside its corner.
  scene.grid.wall(Aabb::of(Vec3(2.01, 2.01, 1.01), Vec3(2.09, 2.09, 1.09)));
  const Vec3 a(1.0, 2.13, 1.05), b(3.0, 2.13, 1.05);
  EXPECT_TRUE(lineOfSight(scene.grid, a, b, true));
  EXPECT_TRUE(tubeOfSight(scene.grid, a, b, 0.0, true));
  EXPECT_FALSE(tubeOfSight(scene.grid, a, b, 0.05, true));
  const Vec3 c(1.0, 2.3, 1.05), d(3.0, 2.3, 1.05);
  EXPECT_TRUE(tubeOfSight(scene.grid, c, d, 0.05, true));
  // Shortcuts keep the tube too: the corner point of this polyline cannot be skipped.
  const std::vector<Vec3> pts{a, Vec3(2.05, 2.4, 1.05), b};
  EXPECT_EQ(shortcutPolyline(scene.grid, pts, true, 0.0).size(), 2u);
  EXPECT_EQ(shortcutPolyline(scene.grid, pts, true, 0.05).size(), 3u);
}

TEST(GraphSearch, OutsideTheWindowPathsFollowTheGraphNotStraightLines) {
  // Grown with the whole map known, searched after the window moved away: nothing in the map
  // says where the wall is, so only the graph (and its polyhedra) keeps paths out of it.
  TwoRoomsScene scene = twoRoomsGrid();
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(1.0, 1.0, 1.2));
  scene.grid.setWindow(Aabb::of(Vec3(20, 20, 0), Vec3(21, 21, 1)));
  const TwoRoomsScene truth = twoRoomsGrid();
  int found = 0;
  for (double y : {0.5, 1.0, 3.0, 3.5})
    for (const Vec3& start : {Vec3(3.6, y, 1.2), Vec3(3.75, y, 0.9)}) {
      const Vec3 goal(4.6, y, 1.2);  // just across the wall
      const GraphPath p = findGraphPath(g, scene.grid, start, goal);
      if (!p.found) continue;
      ++found;
      for (size_t i = 1; i < p.points.size(); ++i)
        for (int k = 0; k <= 200; ++k) {
          const Vec3 q = p.points[i - 1] + (p.points[i] - p.points[i - 1]) * (k / 200.0);
          ASSERT_NE(truth.grid.stateAt(q), VoxelState::Occupied) << "start " << start.transpose() << " at " << q.transpose();
        }
      EXPECT_GT(p.length, 2.0);  // around through the door at y 1.6-2.5
    }
  EXPECT_GE(found, 4);
}

TEST(GraphSearch, ObstaclesSeenLaterAreRecordedAndAvoided) {
  // The room is grown empty; then a pillar is observed in its middle. The graph keeps its nodes
  // but records the pillar in the polyhedra it lies in and blocks the edges through it, so a
  // search made after the window has moved on (the map knows nothing) still goes around it.
  BoxRoomScene scene = boxRoomGrid(Vec3(6.0, 4.0, 2.6));
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(1.0, 2.0, 1.2));
  const Aabb pillar = Aabb::of(Vec3(2.6, 1.0, 0.0), Vec3(3.4, 3.0, 2.6));
  scene.grid.wall(pillar);
  std::vector<Vec3i> seen;
  const double res = scene.grid.resolution();
  for (double x = pillar.min.x() + 0.05; x < pillar.max.x(); x += res)
    for (double y = pillar.min.y() + 0.05; y < pillar.max.y(); y += res)
      for (double z = 0.05; z < 2.6; z += res) seen.push_back(scene.grid.keyOf(Vec3(x, y, z)));
  const GraphUpdateStats st = g.update(scene.grid, Vec3(1.0, 2.0, 1.2), 10.0, seen);
  EXPECT_GT(st.recarved, 0);
  EXPECT_GT(st.blocked_edges, 0);
  for (const ScgEdge& e : g.edges()) {
    if (e.blocked) continue;
    std::vector<Vec3> poly{g.node(e.a).center};
    poly.insert(poly.end(), e.via.begin(), e.via.end());
    poly.push_back(g.node(e.b).center);
    EXPECT_TRUE(polylineClear(scene.grid, poly, false)) << "unblocked edge " << e.a << "-" << e.b << " crosses the pillar";
  }
  const BoxRoomScene truth = [&] {
    BoxRoomScene t = boxRoomGrid(Vec3(6.0, 4.0, 2.6));
    t.grid.wall(pillar);
    return t;
  }();
  scene.grid.setWindow(Aabb::of(Vec3(20, 20, 0), Vec3(21, 21, 1)));
  const GraphPath p = findGraphPath(g, scene.grid, Vec3(2.0, 2.0, 1.2), Vec3(4.0, 2.0, 1.2));
  ASSERT_TRUE(p.found);
  for (size_t i = 1; i < p.points.size(); ++i)
    for (int k = 0; k <= 200; ++k) {
      const Vec3 q = p.points[i - 1] + (p.points[i] - p.points[i - 1]) * (k / 200.0);
      ASSERT_FALSE(pillar.contains(q)) << "path through the pillar at " << q.transpose();
    }
  EXPECT_TRUE(truth.grid.stateAt(p.points.front()) == VoxelState::Free);
}

TEST(GridPath, PolylinePassesNearMeasuresTheDistanceToEachSegment) {
  const std::vector<Vec3> pts{Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(2, 2, 1)};
  auto near = [&](const Vec3& s, double r) { return polylinePassesNear(pts, std::vector<Vec3>{s}, r); };
  EXPECT_TRUE(near(Vec3(1.0, 0.25, 1), 0.3));   // 0.25 m beside the first segment
  EXPECT_FALSE(near(Vec3(1.0, 0.35, 1), 0.3));
  EXPECT_TRUE(near(Vec3(-0.2, 0.1, 1), 0.3));   // 0.22 m from the first point
  EXPECT_FALSE(near(Vec3(-0.3, 0.0, 1), 0.25));  // past the end: the distance is to the end point
  EXPECT_TRUE(near(Vec3(1.8, 1.0, 1), 0.3));    // 0.2 m beside the second segment
  EXPECT_FALSE(near(Vec3(1.0, 1.0, 1), 0.9));   // the corner's inside, 1 m from both
  EXPECT_FALSE(polylinePassesNear(pts, {}, 5.0));
  EXPECT_TRUE(polylinePassesNear({Vec3(0, 0, 0)}, std::vector<Vec3>{Vec3(0.1, 0, 0)}, 0.2));  // a single point
}

TEST(GraphSearch, EdgesPassingAPointToAvoidAreNotUsed) {
  // A room with a pillar in its middle: two ways round it. With a point of the first path's
  // way round to avoid, no edge of the next path comes near it.
  BoxRoomScene scene = boxRoomGrid(Vec3(6.0, 4.0, 2.6));
  scene.grid.wall(Aabb::of(Vec3(2.6, 1.0, 0.0), Vec3(3.4, 3.0, 2.6)));
  ConnectivityGraph g;
  grow(g, scene.grid, Vec3(1.0, 2.0, 1.2));
  grow(g, scene.grid, Vec3(5.0, 2.0, 1.2));
  const Vec3 start(1.0, 2.0, 1.2), goal(5.0, 2.0, 1.2);
  PathSearchOptions opt;
  opt.shortcut = false;
  const GraphPath first = findGraphPath(g, scene.grid, start, goal, opt);
  ASSERT_TRUE(first.found);
  // Where the first path passes the pillar (x = 3).
  std::optional<Vec3> spot;
  for (size_t i = 1; i < first.points.size(); ++i) {
    const Vec3 &a = first.points[i - 1], &b = first.points[i];
    if ((a.x() - 3.0) * (b.x() - 3.0) <= 0.0 && std::abs(b.x() - a.x()) > 1e-9)
      spot = a + (b - a) * ((3.0 - a.x()) / (b.x() - a.x()));
  }
  ASSERT_TRUE(spot.has_value());
  opt.avoid = {*spot};
  opt.avoid_radius = 0.3;
  const GraphPath second = findGraphPath(g, scene.grid, start, goal, opt);
  ASSERT_TRUE(second.found) << "a way round the other side";
  expectClearPolyline(scene.grid, second.points);
  for (size_t i = 1; i < second.nodes.size(); ++i) {
    const int e = g.edgeBetween(second.nodes[i - 1], second.nodes[i]);
    EXPECT_FALSE(polylinePassesNear(g.edgePolyline(e), opt.avoid, opt.avoid_radius))
        << "edge " << second.nodes[i - 1] << "-" << second.nodes[i] << " passes (" << spot->transpose() << ")";
  }
}
