#include <gtest/gtest.h>

#include <array>
#include <set>

#include "support/skeleton_scenes.hpp"
#include "ussnav/skeleton/graph_drawing.hpp"
#include "ussnav/skeleton/graph_metrics.hpp"

using namespace ussnav;
using namespace ussnav::test;

namespace {
ConnectivityGraph grown(const OccupancyMap& map, const Vec3& uav) {
  ConnectivityGraph g;
  for (int f = 0; f < 50; ++f)
    if (g.update(map, uav, 0.1 * f).expansions == 0 && g.queuedSurfaces() == 0) break;
  return g;
}
}  // namespace

TEST(GraphMetrics, StatsCountNodesAndEdgesByType) {
  const TwoRoomsScene scene = twoRoomsGrid();
  const ConnectivityGraph g = grown(scene.grid, Vec3(1.0, 1.0, 1.2));
  const GraphStats s = graphStats(g);
  EXPECT_EQ(s.nodes, int(g.size()));
  EXPECT_EQ(s.edges, int(g.edges().size()));
  int sum = 0;
  for (int t = 0; t < kEdgeTypeCount; ++t) {
    int brute = 0;
    for (const ScgEdge& e : g.edges()) brute += int(e.type) == t;
    EXPECT_EQ(s.edges_by_type[size_t(t)], brute);
    sum += brute;
  }
  EXPECT_EQ(sum, s.edges);
  EXPECT_EQ(s.components, 1);
  EXPECT_NEAR(s.mean_degree, 2.0 * s.edges / s.nodes, 1e-12);
  const nlohmann::json j = toJson(s);
  EXPECT_EQ(j.at("nodes").get<int>(), s.nodes);
  EXPECT_EQ(j.at("edges_by_type").at("kinematic").get<int>(), s.edges_by_type[0]);
  EXPECT_EQ(j.at("edges_by_type").at("loop").get<int>(), s.edges_by_type[3]);
  EXPECT_TRUE(j.contains("deferred_surfaces"));
  EXPECT_EQ(graphStats(ConnectivityGraph{}).components, 0);
}

TEST(GraphMetrics, ComponentsSeparateDisconnectedParts) {
  TwoRoomsScene scene = twoRoomsGrid();
  scene.grid.wall(scene.door);
  ConnectivityGraph g;
  for (int f = 0; f < 30; ++f) g.update(scene.grid, Vec3(1.0, 1.0, 1.2), 0.1 * f);
  for (int f = 30; f < 60; ++f) g.update(scene.grid, Vec3(6.0, 2.0, 1.2), 0.1 * f);
  const std::vector<int> comp = connectedComponents(g);
  EXPECT_EQ(graphStats(g).components, 2);
  for (const ScgNode& n : g.nodes())
    EXPECT_EQ(comp[size_t(n.id)], scene.room_a.contains(n.center) ? comp[0] : 1 - comp[0]);
}

TEST(GraphMetrics, CoverageMatchesBruteForce) {
  BoxRoomScene scene = boxRoomGrid(Vec3(3.0, 2.5, 2.4));
  SkeletonConfig cfg;
  cfg.max_expansions_per_frame = 3;  // a partial graph, so that coverage is well below 1
  ConnectivityGraph g(cfg);
  g.update(scene.grid, Vec3(1.0, 1.0, 1.2), 0.0);
  const CoverageResult cov = freeSpaceCoverage(g, scene.grid, 0.5, 2.0);
  size_t free = 0, covered = 0;
  for (int z = scene.grid.minKey().z(); z <= scene.grid.maxKey().z(); ++z)
    for (int y = scene.grid.minKey().y(); y <= scene.grid.maxKey().y(); ++y)
      for (int x = scene.grid.minKey().x(); x <= scene.grid.maxKey().x(); ++x) {
        const Vec3i k(x, y, z);
        const Vec3 c = scene.grid.centerOf(k);
        if (scene.grid.state(k) != VoxelState::Free || c.z() < 0.5 || c.z() > 2.0) continue;
        ++free;
        for (const ScgNode& n : g.nodes())
          if (n.polyhedron.contains(c)) {
            ++covered;
            break;
          }
      }
  EXPECT_EQ(cov.free_voxels, free);
  EXPECT_EQ(cov.covered_voxels, covered);
  EXPECT_EQ(free, size_t(30 * 25 * 15));
  EXPECT_GT(cov.fraction(), 0.1);
  EXPECT_LT(cov.fraction(), 0.95);
  EXPECT_EQ(freeSpaceCoverage(ConnectivityGraph{}, scene.grid, 0.5, 2.0).covered_voxels, 0u);
}

TEST(GraphDrawing, ConvexOutlineOfPoints) {
  std::vector<Vec2> pts = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2), Vec2(1, 1), Vec2(0.5, 1.5), Vec2(1, 0)};
  const std::vector<Vec2> hull = convexOutline2d(pts);
  ASSERT_EQ(hull.size(), 4u);
  double area = 0;  // shoelace: positive for counter-clockwise
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(0.5 * area, 4.0, 1e-12);
}

TEST(GraphDrawing, DrawsPolyhedraCentresAndTypedEdges) {
  const TwoRoomsScene scene = twoRoomsGrid();
  const ConnectivityGraph g = grown(scene.grid, Vec3(1.0, 1.0, 1.2));
  const TopDownView view = TopDownView::fit(scene.grid.bounds(), 50);
  Image img(view.width, view.height);
  drawConnectivityGraph(img, view, g);
  int satellites = 0;
  for (const ScgNode& n : g.nodes()) {
    const Vec2 p = view.toPx(n.center);
    satellites += n.satellite;  // drawn smaller and grey
    const Rgb expected = n.satellite ? Rgb{120, 120, 120} : Rgb{20, 20, 20};
    EXPECT_EQ(img.at(int(std::lround(p.x())), int(std::lround(p.y()))), expected);
  }
  EXPECT_GT(satellites, 0);
  std::set<Rgb> colours;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) colours.insert(img.at(x, y));
  std::array<int, kEdgeTypeCount> core_edges{};  // edges of satellites are drawn grey
  for (const ScgEdge& e : g.edges()) core_edges[size_t(e.type)] += !g.node(e.a).satellite && !g.node(e.b).satellite;
  for (int t = 0; t < kEdgeTypeCount; ++t)
    if (core_edges[size_t(t)] > 0) {
      EXPECT_TRUE(colours.count(edgeTypeColor(EdgeType(t)))) << edgeTypeName(EdgeType(t));
    }
  EXPECT_TRUE(colours.count(Rgb{175, 175, 175}));
  // A band filter that excludes every centre draws nothing.
  Image blank(view.width, view.height);
  GraphDrawOptions opt;
  opt.z_min = 10.0;
  drawConnectivityGraph(blank, view, g, opt);
  for (int y = 0; y < blank.height(); ++y)
    for (int x = 0; x < blank.width(); ++x) ASSERT_EQ(blank.at(x, y), (Rgb{255, 255, 255}));
}
