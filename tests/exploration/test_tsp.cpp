#include <gtest/gtest.h>

#include <cmath>

#include "ussnav/core/random.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/exploration/tsp.hpp"

using namespace ussnav;

namespace {
// Random points in a 20 m square plus an asymmetric "yaw" term, like viewpoint costs.
CostMatrix randomCosts(int n, uint64_t seed, bool asymmetric) {
  Rng rng(seed);
  std::vector<Vec3> p(n);
  for (auto& q : p) q = Vec3(rng.uniform(0, 20), rng.uniform(0, 20), rng.uniform(-kPi, kPi));
  CostMatrix c(n, std::vector<double>(n, 0.0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j) {
        const double d = (p[i].head<2>() - p[j].head<2>()).norm();
        c[i][j] = asymmetric ? std::max(d, std::abs(wrapAngle(p[j].z() - p[i].z())) * (i < j ? 1.0 : 1.5)) : d;
      }
  return c;
}
}  // namespace

TEST(Tsp, ExactMatchesBruteForceUpToNinePoints) {
  for (int n = 1; n <= 9; ++n)
    for (uint64_t seed = 1; seed <= 4; ++seed)
      for (bool asym : {false, true}) {
        const CostMatrix c = randomCosts(n + 1, seed * 31 + n, asym);
        const TspResult dp = solveOpenTsp(c);
        const TspResult bf = bruteForceOpenTsp(c);
        EXPECT_TRUE(dp.exact);
        EXPECT_NEAR(dp.cost, bf.cost, 1e-9) << "n=" << n << " seed=" << seed;
        EXPECT_NEAR(openTourCost(c, dp.order), dp.cost, 1e-9);
        EXPECT_EQ(int(dp.order.size()), n);
      }
}

TEST(Tsp, HeuristicMatchesBruteForceOnSmallSetsMostly) {
  // Force the heuristic path (exact_limit 0) and compare with the optimum.
  int optimal = 0, total = 0;
  double worst_ratio = 1.0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const CostMatrix c = randomCosts(9, seed, false);
    const TspResult h = solveOpenTsp(c, 0);
    const TspResult bf = bruteForceOpenTsp(c);
    EXPECT_FALSE(h.exact);
    EXPECT_GE(h.cost, bf.cost - 1e-9);
    worst_ratio = std::max(worst_ratio, h.cost / bf.cost);
    optimal += std::abs(h.cost - bf.cost) < 1e-9;
    ++total;
  }
  EXPECT_GE(optimal, total * 3 / 4) << "2-opt + Or-opt should find most 8-point optima";
  EXPECT_LT(worst_ratio, 1.10);
}

TEST(Tsp, VisitsEveryNodeOnceForLargeSets) {
  const CostMatrix c = randomCosts(101, 7, true);
  const TspResult r = solveOpenTsp(c);
  std::vector<int> seen(101, 0);
  for (int j : r.order) ++seen[j];
  EXPECT_EQ(seen[0], 0);
  for (int j = 1; j <= 100; ++j) EXPECT_EQ(seen[j], 1);
  // Local search never worse than nearest-neighbour alone: compare with the plain NN tour.
  std::vector<bool> used(101, false);
  std::vector<int> nn;
  int cur = 0;
  for (int s = 0; s < 100; ++s) {
    int b = -1;
    for (int j = 1; j <= 100; ++j)
      if (!used[j] && (b < 0 || c[cur][j] < c[cur][b])) b = j;
    used[b] = true;
    nn.push_back(b);
    cur = b;
  }
  EXPECT_LE(r.cost, openTourCost(c, nn) + 1e-9);
}

TEST(Tsp, CollinearPointsAreVisitedInOrder) {
  // Start at x=0, viewpoints at x = 3, 1, 2: the optimal open tour is 1, 2, 3 (cost 3).
  const std::vector<double> x{0, 3, 1, 2};
  CostMatrix c(4, std::vector<double>(4));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) c[i][j] = std::abs(x[i] - x[j]);
  const TspResult r = solveOpenTsp(c);
  EXPECT_EQ(r.order, (std::vector<int>{2, 3, 1}));
  EXPECT_DOUBLE_EQ(r.cost, 3.0);
}

TEST(Tsp, RejectsBadMatrices) {
  EXPECT_THROW(solveOpenTsp({{0, 1}, {1}}), std::invalid_argument);
  EXPECT_THROW(solveOpenTsp({{0, -1}, {1, 0}}), std::invalid_argument);
  EXPECT_EQ(solveOpenTsp({{0}}).order.size(), 0u);
}
