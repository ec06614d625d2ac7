#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ussnav/regions/consolidation.hpp"
#include "ussnav/regions/leiden.hpp"
#include "ussnav/regions/partition_metrics.hpp"

using namespace ussnav;

namespace {

// w x h lattice of nodes 1 m apart, 4-neighbour links of weight 1, ids first + b * w + a.
void addLattice(WeightedGraphView& g, int first, int w, int h, double x0) {
  for (int b = 0; b < h; ++b)
    for (int a = 0; a < w; ++a) {
      const int id = first + b * w + a;
      g.node_ids.push_back(id);
      g.centroids.emplace_back(x0 + a, b, 1.2);
      if (a + 1 < w) g.edges.emplace_back(id, id + 1, 1.0);
      if (b + 1 < h) g.edges.emplace_back(id, id + w, 1.0);
    }
}

// Two w x w lattices side by side (ids 0.. and 100..), joined across the gap between their
// facing columns by `links` edges of `weight` on rows 0..links-1.
IndexedGraph twoRooms(int w, int links, double weight) {
  WeightedGraphView g;
  addLattice(g, 0, w, w, 0.0);
  addLattice(g, 100, w, w, w + 1.0);
  for (int b = 0; b < links; ++b) g.edges.emplace_back(b * w + w - 1, 100 + b * w, weight);
  return indexGraph(g);
}

int communitiesOf(std::vector<int> labels) { return compactLabels(labels); }

}  // namespace

TEST(Leiden, TwoDenseClustersJoinedByAForcedEdgeSplitInTwo) {
  const IndexedGraph g = twoRooms(4, 1, 0.01);
  const LeidenResult r = leiden(g.size(), g.edges, {});
  EXPECT_EQ(r.communities, 2);
  const int left = r.membership[0], right = r.membership[g.size() - 1];
  EXPECT_NE(left, right);
  for (int i = 0; i < g.size(); ++i)  // ids < 100 form the left room
    EXPECT_EQ(r.membership[i], g.ids[i] < 100 ? left : right) << g.ids[i];
}

TEST(Leiden, QualityIsIgraphsCpmOverTotalWeight) {
  const IndexedGraph g = twoRooms(4, 2, 1.0);
  const LeidenResult r = leiden(g.size(), g.edges, {0.02, 0.01, -1, 7});
  double m = 0.0;
  for (const auto& e : g.edges) m += e.w;
  // Two 4x4 lattices: 24 inner edges each; CPM = 2 * (24 - 0.02 * 16^2 / 2) = 42.88.
  EXPECT_EQ(r.communities, 2);
  EXPECT_NEAR(cpmQuality(g, r.membership, 0.02), 42.88, 1e-9);
  EXPECT_NEAR(r.quality, cpmQuality(g, r.membership, 0.02) / m, 1e-9);
}

TEST(Leiden, CpmResolutionDecidesWhenADoorSplits) {
  // 4x4 rooms (16 nodes each) with a 2-edge door: apart while 2 < resolution * 16 * 16.
  const IndexedGraph g = twoRooms(4, 2, 1.0);
  EXPECT_EQ(leiden(g.size(), g.edges, {0.02, 0.01, -1, 1}).communities, 2);  // 2 < 5.12
  EXPECT_EQ(leiden(g.size(), g.edges, {0.005, 0.01, -1, 1}).communities, 1);  // 2 > 1.28
}

TEST(Leiden, DeterministicForASeedAndWarmStartKeepsAStablePartition) {
  const IndexedGraph g = twoRooms(5, 1, 1.0);
  const LeidenResult a = leiden(g.size(), g.edges, {0.02, 0.01, -1, 42});
  const LeidenResult b = leiden(g.size(), g.edges, {0.02, 0.01, -1, 42});
  EXPECT_EQ(a.membership, b.membership);
  // Starting from the converged partition must terminate and keep it (igraph 0.10's own
  // "until stable" loop would spin forever here).
  const LeidenResult warm = leiden(g.size(), g.edges, {0.02, 0.01, -1, 3}, &a.membership);
  EXPECT_EQ(communitiesOf(warm.membership), 2);
  std::vector<int> x = a.membership, y = warm.membership;
  compactLabels(x);
  compactLabels(y);
  EXPECT_EQ(x, y);
}

TEST(Leiden, EdgeCases) {
  EXPECT_TRUE(leiden(0, {}, {}).membership.empty());
  const LeidenResult one = leiden(1, {}, {});
  EXPECT_EQ(one.membership, std::vector<int>{0});
  const LeidenResult lonely = leiden(3, {}, {});  // no edges: every node alone
  EXPECT_EQ(lonely.communities, 3);
  EXPECT_THROW(leiden(2, {{0, 2, 1.0}}, {}), std::invalid_argument);
  EXPECT_THROW(leiden(2, {{0, 0, 1.0}}, {}), std::invalid_argument);
  EXPECT_THROW(leiden(2, {{0, 1, 1.0}}, {0.02, 0.01, 0, 1}), std::invalid_argument);
  const std::vector<int> wrong_size{0};
  EXPECT_THROW(leiden(2, {{0, 1, 1.0}}, {}, &wrong_size), std::invalid_argument);
  // Labels far above n are compacted before igraph sees them.
  const std::vector<int> big{1000, 5000};
  EXPECT_EQ(leiden(2, {{0, 1, 1.0}}, {}, &big).communities, 1);
}

TEST(Consolidation, BorderNodesCountEachNodeOncePerPairAndIgnoreForcedEdges) {
  // Left room ids < 100, right room >= 100; 3 door edges on rows 0-2 and a forced link on
  // row 3. Node (3, 0) also gets a second edge into the right room: still one border node.
  WeightedGraphView v;
  addLattice(v, 0, 4, 4, 0.0);
  addLattice(v, 100, 4, 4, 5.0);
  for (int b = 0; b < 3; ++b) v.edges.emplace_back(b * 4 + 3, 100 + b * 4, 1.0);
  v.edges.emplace_back(3, 104, 1.0);
  v.edges.emplace_back(15, 112, 0.01);
  const IndexedGraph g = indexGraph(v);
  std::vector<int> labels(g.size());
  for (int i = 0; i < g.size(); ++i) labels[i] = g.ids[i] >= 100 ? 1 : 0;
  const auto shared = sharedBorderNodes(g, labels, 0.5);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_EQ(shared.at({0, 1}), 6);  // left 3, 7, 11; right 100, 104, 108
  EXPECT_EQ(sharedBorderNodes(g, labels, 0.0).at({0, 1}), 8);  // forced link counted too
}

TEST(Consolidation, MergesAWideOpeningButNotADoor) {
  // 5x5 rooms: Leiden splits them even across a 5-edge opening (5 < 0.02 * 25 * 25).
  for (int links : {2, 5}) {
    const IndexedGraph g = twoRooms(5, links, 1.0);
    std::vector<int> labels = leiden(g.size(), g.edges, {}).membership;
    ASSERT_EQ(communitiesOf(labels), 2) << links;
    const int merges = consolidate(g, labels, {4, 0.5, 3});
    // A 2-edge door has 4 border nodes (not more than 4): kept apart. 5 edges: 10, merged.
    EXPECT_EQ(merges, links == 5 ? 1 : 0);
    EXPECT_EQ(communitiesOf(labels), links == 5 ? 1 : 2);
  }
  const IndexedGraph g = twoRooms(5, 5, 1.0);
  std::vector<int> labels = leiden(g.size(), g.edges, {}).membership;
  EXPECT_EQ(consolidate(g, labels, {10, 0.5, 3}), 0);  // threshold at the 10 border nodes
}

TEST(Consolidation, TinyCommunitiesJoinTheirMostConnectedNeighbour) {
  // Room A (ids 0..15) and room B (100..115); node 50 hangs off A by two edges of weight 1
  // and off B by one; node 60 has no edges at all.
  WeightedGraphView v;
  addLattice(v, 0, 4, 4, 0.0);
  addLattice(v, 100, 4, 4, 6.0);
  v.node_ids.insert(v.node_ids.end(), {50, 60});
  v.centroids.emplace_back(4.5, 0, 1.2);
  v.centroids.emplace_back(20, 0, 1.2);
  v.edges.emplace_back(50, 3, 1.0);
  v.edges.emplace_back(50, 7, 1.0);
  v.edges.emplace_back(50, 100, 1.0);
  const IndexedGraph g = indexGraph(v);
  std::vector<int> labels(g.size());
  for (int i = 0; i < g.size(); ++i)
    labels[i] = g.ids[i] < 50 ? 0 : g.ids[i] == 50 ? 1 : g.ids[i] == 60 ? 2 : 3;
  const int merges = consolidate(g, labels, {4, 0.5, 3});
  EXPECT_EQ(merges, 1);
  EXPECT_EQ(labels[g.indexOf(50)], labels[g.indexOf(0)]);
  EXPECT_NE(labels[g.indexOf(50)], labels[g.indexOf(100)]);
  const std::set<int> distinct(labels.begin(), labels.end());
  EXPECT_EQ(distinct.size(), 3u);  // A+50, B, and the isolated 60 that has nobody to join
  EXPECT_EQ(*distinct.rbegin(), 2);  // compacted to 0..2
}

namespace {

// Two 5 x h lattices, x in [0, 4] and [6, 10], joined only by crossing edges from (4, b) to
// (6, b') with b + b' in `sums`: each crosses the wall x = 5 at y = (b + b') / 2, so a sum s
// is a door at y = s / 2.
IndexedGraph roomsThroughDoors(int h, const std::vector<int>& sums) {
  WeightedGraphView v;
  addLattice(v, 0, 5, h, 0.0);
  addLattice(v, 100, 5, h, 6.0);
  for (int b = 0; b < h; ++b)
    for (int c = 0; c < h; ++c)
      if (std::find(sums.begin(), sums.end(), b + c) != sums.end()) v.edges.emplace_back(b * 5 + 4, 100 + c * 5, 1.0);
  return indexGraph(v);
}

std::vector<int> bySide(const IndexedGraph& g) {
  std::vector<int> labels(g.size());
  for (int i = 0; i < g.size(); ++i) labels[i] = g.ids[i] >= 100 ? 1 : 0;
  return labels;
}

}  // namespace

TEST(Consolidation, TheOpeningIsTheNarrowestCrossSectionOfTheCrossingEdges) {
  {  // Rows 0..4 linked straight across: a plane that cuts 3/4 of them cuts four rows at least,
     // 3 m apart (4 m for all five across x = 5).
    const IndexedGraph g = twoRooms(5, 5, 1.0);
    const double w = crossingOpening(g, bySide(g), 0, 1, 0.5);
    EXPECT_GE(w, 3.0);
    EXPECT_LE(w, 4.0 + 1e-9);
    EXPECT_NEAR(crossingOpening(g, bySide(g), 0, 1, 2.0), 0.0, 1e-9);  // no edge heavy enough
  }
  {  // Nine edges fanning through one door: they cross x = 5 at y = 2 and 2.5.
    const IndexedGraph g = roomsThroughDoors(5, {4, 5});
    const double w = crossingOpening(g, bySide(g), 0, 1, 0.5);
    EXPECT_LE(w, 0.5 + 1e-9);
    EXPECT_GT(w, 0.0);
  }
  {  // Two such doors 6 m apart in one wall: two openings, each as narrow as one door.
    const IndexedGraph g = roomsThroughDoors(12, {4, 5, 16, 17});
    EXPECT_LE(crossingOpening(g, bySide(g), 0, 1, 0.5), 0.5 + 1e-9);
  }
  {  // One crossing edge: no width.
    const IndexedGraph g = twoRooms(5, 1, 1.0);
    EXPECT_NEAR(crossingOpening(g, bySide(g), 0, 1, 0.5), 0.0, 1e-9);
  }
  {  // Eight radial edges round a circle (from radius 2.5 to 3.5, every 45 degrees): no line
     // cuts 3/4 of them, so no single opening: the extent of their midpoints, a 6 x 6 m box.
    WeightedGraphView v;
    for (int k = 0; k < 8; ++k) {
      const double a = k * 3.14159265358979323846 / 4.0;
      v.node_ids.insert(v.node_ids.end(), {k, 100 + k});
      v.centroids.emplace_back(2.5 * std::cos(a), 2.5 * std::sin(a), 1.2);
      v.centroids.emplace_back(3.5 * std::cos(a), 3.5 * std::sin(a), 1.2);
      v.edges.emplace_back(k, 100 + k, 1.0);
    }
    const IndexedGraph g = indexGraph(v);
    EXPECT_NEAR(crossingOpening(g, bySide(g), 0, 1, 0.5), std::hypot(6.0, 6.0), 1e-9);
  }
}

TEST(Consolidation, AMinimumOpeningKeepsRoomsApartThatShareManyBorderNodesThroughADoor) {
  const IndexedGraph door = roomsThroughDoors(5, {4, 5});
  ASSERT_EQ(sharedBorderNodes(door, bySide(door), 0.5).at({0, 1}), 10);
  std::vector<int> labels = bySide(door);
  EXPECT_EQ(consolidate(door, labels, {4, 0.5, 3, 0.0}), 1);  // counted only: merged
  labels = bySide(door);
  EXPECT_EQ(consolidate(door, labels, {4, 0.5, 3, 1.0}), 0);  // through a 0.5 m door: apart
  EXPECT_EQ(communitiesOf(labels), 2);
  const IndexedGraph open = twoRooms(5, 5, 1.0);
  labels = bySide(open);
  EXPECT_EQ(consolidate(open, labels, {4, 0.5, 3, 1.0}), 1);  // a 4 m opening: merged
  EXPECT_EQ(communitiesOf(labels), 1);
}
