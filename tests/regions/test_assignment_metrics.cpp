#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "ussnav/core/random.hpp"
#include "ussnav/regions/assignment.hpp"
#include "ussnav/regions/partition_metrics.hpp"

using namespace ussnav;

namespace {

double total(const std::vector<std::vector<double>>& s, const std::vector<int>& match) {
  double t = 0.0;
  for (size_t r = 0; r < match.size(); ++r)
    if (match[r] >= 0) t += s[r][match[r]];
  return t;
}

// Best total over all injective maps of the smaller side into the larger.
double bruteForce(const std::vector<std::vector<double>>& s) {
  const int rows = static_cast<int>(s.size()), cols = static_cast<int>(s[0].size());
  std::vector<int> perm(std::max(rows, cols));
  std::iota(perm.begin(), perm.end(), 0);
  double best = -1e300;
  do {
    double t = 0.0;
    for (int r = 0; r < rows; ++r)
      if (perm[r] < cols) t += s[r][perm[r]];
    best = std::max(best, t);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

}  // namespace

TEST(Assignment, PicksTheOptimumNotTheGreedyChoice) {
  // Greedy takes (0,0)=9 and then (1,1)=1 -> 10; the optimum is 8 + 8 = 16.
  const std::vector<std::vector<double>> s{{9, 8}, {8, 1}};
  EXPECT_EQ(maxScoreAssignment(s), (std::vector<int>{1, 0}));
}

TEST(Assignment, MatchesBruteForceOnRandomRectangularMatrices) {
  Rng rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = rng.uniformInt(1, 5), cols = rng.uniformInt(1, 5);
    std::vector<std::vector<double>> s(rows, std::vector<double>(cols));
    for (auto& row : s)
      for (double& x : row) x = static_cast<double>(rng.uniformInt(0, 6));  // with ties
    const std::vector<int> m = maxScoreAssignment(s);
    ASSERT_EQ(static_cast<int>(m.size()), rows);
    std::vector<int> used;
    for (int c : m)
      if (c >= 0) used.push_back(c);
    std::sort(used.begin(), used.end());
    EXPECT_EQ(std::adjacent_find(used.begin(), used.end()), used.end()) << "column reused";
    EXPECT_EQ(static_cast<int>(used.size()), std::min(rows, cols));
    EXPECT_DOUBLE_EQ(total(s, m), bruteForce(s)) << "trial " << trial;
  }
}

TEST(Assignment, EmptyAndBadInput) {
  EXPECT_TRUE(maxScoreAssignment({}).empty());
  EXPECT_EQ(maxScoreAssignment({{}, {}}), (std::vector<int>{-1, -1}));
  EXPECT_THROW(maxScoreAssignment({{1, 2}, {3}}), std::invalid_argument);
  EXPECT_THROW(maxScoreAssignment({{std::nan("")}}), std::invalid_argument);
}

TEST(PartitionMetrics, HandComputedContingencyTable) {
  // predicted: 0 0 0 1 1 1      contingency   truth 0  1  2  | rows
  // truth:     0 0 1 1 2 2      cluster 0        2  1  0  |  3
  //                             cluster 1        0  1  2  |  3
  // purity = (2 + 2) / 6. Pair counts: index = C(2,2) + C(2,2) = 2, rows a = 3 + 3 = 6,
  // columns b = 1 + 1 + 1 = 3, C(6,2) = 15, expected = 6 * 3 / 15 = 1.2, max = 4.5,
  // ARI = (2 - 1.2) / (4.5 - 1.2) = 0.8 / 3.3.
  const std::vector<int> pred{0, 0, 0, 1, 1, 1}, truth{0, 0, 1, 1, 2, 2};
  EXPECT_NEAR(purity(pred, truth), 4.0 / 6.0, 1e-12);
  EXPECT_NEAR(adjustedRandIndex(pred, truth), 0.8 / 3.3, 1e-12);
  // The textbook case: splitting one of two classes. index 1, a 1, b 2, C(4,2) 6:
  // (1 - 1/3) / (1.5 - 1/3) = 4/7.
  EXPECT_NEAR(adjustedRandIndex({0, 0, 1, 2}, {0, 0, 1, 1}), 4.0 / 7.0, 1e-12);
  EXPECT_NEAR(purity({0, 0, 1, 2}, {0, 0, 1, 1}), 1.0, 1e-12);  // splitting keeps purity
}

TEST(PartitionMetrics, InvariantToLabelNamesAndEdgeCases) {
  EXPECT_DOUBLE_EQ(adjustedRandIndex({7, 7, 3, 3}, {0, 0, 1, 1}), 1.0);
  EXPECT_DOUBLE_EQ(purity({7, 7, 3, 3}, {0, 0, 1, 1}), 1.0);
  EXPECT_DOUBLE_EQ(purity({0, 0, 0, 0}, {0, 0, 1, 1}), 0.5);
  // Everything in one cluster against two classes: no agreement beyond chance.
  EXPECT_NEAR(adjustedRandIndex({0, 0, 0, 0}, {0, 0, 1, 1}), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(adjustedRandIndex({1, 1, 1}, {4, 4, 4}), 1.0);
  EXPECT_DOUBLE_EQ(adjustedRandIndex({1, 2, 3}, {4, 5, 6}), 1.0);
  EXPECT_DOUBLE_EQ(adjustedRandIndex({}, {}), 1.0);
  EXPECT_DOUBLE_EQ(purity({}, {}), 1.0);
  EXPECT_LT(adjustedRandIndex({0, 1, 0, 1}, {0, 0, 1, 1}), 0.0);  // worse than chance
  EXPECT_THROW(purity({0}, {0, 1}), std::invalid_argument);
  EXPECT_THROW(adjustedRandIndex({0}, {0, 1}), std::invalid_argument);
}

TEST(PartitionMetrics, CpmQualityByHand) {
  // Triangle 1-2-3 (weights 1, 1, 0.5) and a pendant 4 linked to 3 with weight 1.
  WeightedGraphView v;
  v.node_ids = {1, 2, 3, 4};
  v.centroids.assign(4, Vec3::Zero());
  v.edges = {{1, 2, 1.0}, {2, 3, 1.0}, {1, 3, 0.5}, {3, 4, 1.0}};
  const IndexedGraph g = indexGraph(v);
  // {1,2,3} {4}: 2.5 - 0.1 * 9 / 2 - 0.1 * 1 / 2 = 2.0; all together: 3.5 - 0.1 * 16 / 2 = 2.7.
  EXPECT_NEAR(cpmQuality(g, {0, 0, 0, 1}, 0.1), 2.0, 1e-12);
  EXPECT_NEAR(cpmQuality(g, {5, 5, 5, 5}, 0.1), 2.7, 1e-12);
  EXPECT_THROW(cpmQuality(g, {0}, 0.1), std::invalid_argument);
}
