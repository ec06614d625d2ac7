#include <gtest/gtest.h>

#include "ussnav/core/error.hpp"
#include "ussnav/regions/graph_view.hpp"

using namespace ussnav;

namespace {

WeightedGraphView pathGraph(const std::vector<int>& ids) {
  WeightedGraphView g;
  for (size_t i = 0; i < ids.size(); ++i) {
    g.node_ids.push_back(ids[i]);
    g.centroids.emplace_back(double(i), 0.0, 1.0);
    if (i > 0) g.edges.emplace_back(ids[i - 1], ids[i], 1.0);
  }
  return g;
}

std::string errorOf(const WeightedGraphView& g) {
  try {
    indexGraph(g, "scg");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GraphView, IndexesByAscendingIdWhateverTheInputOrder) {
  WeightedGraphView g = pathGraph({30, 10, 20});  // path 30 - 10 - 20
  const IndexedGraph ig = indexGraph(g);
  ASSERT_EQ(ig.ids, (std::vector<int>{10, 20, 30}));
  EXPECT_EQ(ig.indexOf(30), 2);
  EXPECT_EQ(ig.indexOf(31), -1);
  EXPECT_DOUBLE_EQ(ig.centroids[2].x(), 0.0);  // node 30 was first in the view
  ASSERT_EQ(ig.edges.size(), 2u);
  EXPECT_EQ(ig.edges[0].u, 0);  // (10, 20)
  EXPECT_EQ(ig.edges[0].v, 1);
  EXPECT_EQ(ig.edges[1].u, 0);  // (10, 30)
  EXPECT_EQ(ig.edges[1].v, 2);
  // CSR: node 10 links to 20 and 30, node 20 only to 10.
  EXPECT_EQ(ig.offsets, (std::vector<int>{0, 2, 3, 4}));
  EXPECT_EQ(ig.nbrs, (std::vector<int>{1, 2, 0, 0}));
}

TEST(GraphView, DuplicateEdgesKeepTheStrongestAndSelfLoopsGo) {
  WeightedGraphView g = pathGraph({1, 2});
  g.edges.emplace_back(2, 1, 0.01);  // forced link listed again, reversed
  g.edges.emplace_back(1, 2, 0.5);
  g.edges.emplace_back(2, 2, 1.0);
  const IndexedGraph ig = indexGraph(g);
  ASSERT_EQ(ig.edges.size(), 1u);
  EXPECT_DOUBLE_EQ(ig.edges[0].w, 1.0);
  EXPECT_EQ(ig.nbrs.size(), 2u);
}

TEST(GraphView, SparseIdsUseTheHashLookup) {
  const IndexedGraph ig = indexGraph(pathGraph({-5, 1000000, 7, 2000000000}));
  EXPECT_EQ(ig.indexOf(-5), 0);
  EXPECT_EQ(ig.indexOf(7), 1);
  EXPECT_EQ(ig.indexOf(2000000000), 3);
  EXPECT_EQ(ig.indexOf(8), -1);
  EXPECT_EQ(ig.edges.size(), 3u);
}

TEST(GraphView, BadInputNamesSourceAndField) {
  WeightedGraphView g = pathGraph({1, 2, 3});
  g.centroids.pop_back();
  EXPECT_NE(errorOf(g).find("centroids"), std::string::npos);

  g = pathGraph({1, 2, 1});
  EXPECT_NE(errorOf(g).find("duplicate node id 1"), std::string::npos);

  g = pathGraph({1, 2, 3});
  g.edges.emplace_back(3, 9, 1.0);
  const std::string e = errorOf(g);
  EXPECT_NE(e.find("scg"), std::string::npos) << e;
  EXPECT_NE(e.find("edges[2]"), std::string::npos) << e;
  EXPECT_NE(e.find("node id 9"), std::string::npos) << e;

  g = pathGraph({1, 2});
  std::get<2>(g.edges[0]) = -1.0;
  EXPECT_NE(errorOf(g).find("weight"), std::string::npos);
  std::get<2>(g.edges[0]) = std::nan("");
  EXPECT_NE(errorOf(g).find("weight"), std::string::npos);

  g = pathGraph({1, 2});
  g.centroids[1].y() = std::numeric_limits<double>::infinity();
  EXPECT_NE(errorOf(g).find("centroids[1]"), std::string::npos);
}

TEST(GraphView, InducedSubgraphKeepsOnlyInnerEdges) {
  // 4-cycle 1-2-3-4-1 plus chord 1-3 (weight 0.5); keep {1, 3, 4}.
  WeightedGraphView g = pathGraph({1, 2, 3, 4});
  g.edges.emplace_back(4, 1, 1.0);
  g.edges.emplace_back(1, 3, 0.5);
  const IndexedGraph ig = indexGraph(g);
  const IndexedGraph sub = inducedSubgraph(ig, {0, 2, 3});
  ASSERT_EQ(sub.ids, (std::vector<int>{1, 3, 4}));
  ASSERT_EQ(sub.edges.size(), 3u);  // 1-3, 1-4, 3-4
  EXPECT_EQ(sub.edges[0].v, 1);
  EXPECT_DOUBLE_EQ(sub.edges[0].w, 0.5);
  EXPECT_EQ(sub.edges[1].v, 2);
  EXPECT_EQ(sub.edges[2].u, 1);
  EXPECT_EQ(sub.indexOf(4), 2);
  EXPECT_EQ(sub.indexOf(2), -1);
}

TEST(GraphView, AdaptorBuildsAViewFromAnyGraph) {
  struct Node { int id; double x; };
  struct Link { int a, b; bool forced; };
  const std::vector<Node> nodes{{4, 0.0}, {5, 1.0}};
  const std::vector<Link> links{{4, 5, true}};
  const WeightedGraphView v = makeGraphView(
      nodes, [](const Node& n) { return std::pair<int, Vec3>(n.id, Vec3(n.x, 0, 0)); }, links,
      [](const Link& l) { return std::tuple<int, int, double>(l.a, l.b, l.forced ? 0.01 : 1.0); });
  EXPECT_EQ(v.node_ids, (std::vector<int>{4, 5}));
  EXPECT_DOUBLE_EQ(v.centroids[1].x(), 1.0);
  EXPECT_DOUBLE_EQ(std::get<2>(v.edges[0]), 0.01);
}
