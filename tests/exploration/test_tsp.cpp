#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

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

namespace {
// Brute force over all orders for the search objective (n - 1 <= 8).
double bruteSearch(const CostMatrix& c, const std::vector<double>& w) {
  std::vector<int> perm(c.size() - 1);
  std::iota(perm.begin(), perm.end(), 1);
  double best = 1e300;
  do best = std::min(best, searchTourCost(c, w, perm));
  while (std::next_permutation(perm.begin(), perm.end()));
  return perm.empty() ? 0.0 : best;
}
std::vector<double> randomWeights(int n, uint64_t seed) {
  Rng rng(seed);
  std::vector<double> w(n);
  for (double& x : w) x = rng.uniform(0, 300);
  return w;
}
}  // namespace

TEST(SearchTour, ObjectiveMatchesHandComputedArrivals) {
  // Start 0 at x=0, targets at x = 1 (weight 1), 2 (weight 10). Order 1,2: arrivals 1 and 2 ->
  // 1*1 + 10*2 = 21. Order 2,1: arrivals 2 and 3 -> 10*2 + 1*3 = 23.
  const std::vector<double> x{0, 1, 2};
  CostMatrix c(3, std::vector<double>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = std::abs(x[i] - x[j]);
  const std::vector<double> w{99, 1, 10};  // weight of the start is ignored
  EXPECT_DOUBLE_EQ(searchTourCost(c, w, {1, 2}), 21.0);
  EXPECT_DOUBLE_EQ(searchTourCost(c, w, {2, 1}), 23.0);
  EXPECT_EQ(solveSearchTour(c, w).order, (std::vector<int>{1, 2}));
}

TEST(SearchTour, LargeTargetBeforeANearerSliver) {
  // A sliver 1 m to the left (weight 1), a big unknown room 3 m to the right (weight 100). The
  // distance TSP takes the sliver first (1 + 4 = 5 < 3 + 4 = 7); the search tour flies to the
  // room first: 100*3 + 1*7 = 307 < 1*1 + 100*5 = 501.
  const std::vector<double> x{0, -1, 3};
  CostMatrix c(3, std::vector<double>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = std::abs(x[i] - x[j]);
  const std::vector<double> w{0, 1, 100};
  EXPECT_EQ(solveOpenTsp(c).order, (std::vector<int>{1, 2}));
  const TspResult s = solveSearchTour(c, w);
  EXPECT_EQ(s.order, (std::vector<int>{2, 1}));
  EXPECT_DOUBLE_EQ(s.cost, 307.0);
  // Equal weights: the search tour still differs from the distance tour only by its objective.
  EXPECT_EQ(solveSearchTour(c, {0, 1, 1}).order, (std::vector<int>{1, 2}));
}

TEST(SearchTour, ExactMatchesBruteForceAndHeuristicIsClose) {
  int optimal = 0, total = 0;
  for (int n = 1; n <= 8; ++n)
    for (uint64_t seed = 1; seed <= 4; ++seed)
      for (bool asym : {false, true}) {
        const CostMatrix c = randomCosts(n + 1, seed * 17 + n, asym);
        const auto w = randomWeights(n + 1, seed * 5 + n);
        const double bf = bruteSearch(c, w);
        const TspResult dp = solveSearchTour(c, w);
        EXPECT_TRUE(dp.exact);
        EXPECT_NEAR(dp.cost, bf, 1e-6 * std::max(1.0, bf)) << "n=" << n << " seed=" << seed;
        EXPECT_NEAR(searchTourCost(c, w, dp.order), dp.cost, 1e-9 * std::max(1.0, bf));
        const TspResult h = solveSearchTour(c, w, 0);
        EXPECT_FALSE(h.exact);
        EXPECT_GE(h.cost, bf - 1e-6 * std::max(1.0, bf));
        EXPECT_LT(h.cost, 1.15 * bf + 1e-9);
        optimal += std::abs(h.cost - bf) <= 1e-6 * std::max(1.0, bf);
        ++total;
      }
  EXPECT_GE(optimal, total * 3 / 4);
}

TEST(SearchTour, RejectsBadWeights) {
  const CostMatrix c{{0, 1}, {1, 0}};
  EXPECT_THROW(solveSearchTour(c, {0}), std::invalid_argument);
  EXPECT_THROW(solveSearchTour(c, {0, -1}), std::invalid_argument);
  EXPECT_EQ(solveSearchTour({{0}}, {0}).order.size(), 0u);
}
