#pragma once
// Open-tour travelling salesman over viewpoints (paper Sec. V-B, fine level; FUEL's global
// tour). Node 0 is the UAV: the tour starts there and ends anywhere. Costs may be asymmetric
// (yaw change depends on the direction of travel). Exact Held-Karp dynamic programming up to
// `exact_limit` viewpoints (O(2^n n^2)), above that nearest-neighbour + 2-opt + Or-opt local
// search until no move improves (O(n^2) per sweep).

#include <vector>

namespace ussnav {

// cost[i][j]: cost of going from i to j; node 0 is the start. Square, finite, >= 0.
using CostMatrix = std::vector<std::vector<double>>;

struct TspResult {
  std::vector<int> order;  // visiting order of nodes 1..n-1 (the start 0 excluded)
  double cost = 0.0;       // sum of costs along 0 -> order[0] -> ... (search tour: its objective)
  bool exact = false;      // solved by dynamic programming
};

// Solves the open tour. Throws std::invalid_argument on a non-square or negative matrix.
TspResult solveOpenTsp(const CostMatrix& cost, int exact_limit = 12);

// Cost of an open tour 0 -> order...
double openTourCost(const CostMatrix& cost, const std::vector<int>& order);

// Search tour: the open tour that minimises sum_j weight[j] * arrival_j, the expected time to
// reach what is sought when it lies behind viewpoint j with probability proportional to
// weight[j] (the minimum-latency, or graph-search, form of the TSP). A plain TSP takes the
// nearest small target first because every target counts alike; this one visits a large,
// near target before a small, nearer one. weight[0] (the start) is ignored; same exact/local
// search split as solveOpenTsp. Throws std::invalid_argument on a bad matrix or weight.
TspResult solveSearchTour(const CostMatrix& cost, const std::vector<double>& weight, int exact_limit = 12);

// sum_j weight[j] * arrival_j of an open tour 0 -> order...
double searchTourCost(const CostMatrix& cost, const std::vector<double>& weight, const std::vector<int>& order);

// Brute force over all permutations (tests only; n - 1 <= 9).
TspResult bruteForceOpenTsp(const CostMatrix& cost);

}  // namespace ussnav
