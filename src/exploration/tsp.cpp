#include "ussnav/exploration/tsp.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ussnav {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void checkMatrix(const CostMatrix& c) {
  for (const auto& row : c) {
    if (row.size() != c.size()) throw std::invalid_argument("TSP cost matrix is not square");
    for (double v : row)
      if (!(v >= 0.0) || std::isinf(v)) throw std::invalid_argument("TSP cost must be finite and >= 0");
  }
}

// Exact dynamic programming over subsets. With `weight` empty the path cost is the sum of the
// edges; with weights each edge is paid once per unit of weight not yet visited (so the sum is
// sum_j weight_j * arrival_j: the remaining weight of a subset does not depend on the order).
TspResult heldKarp(const CostMatrix& c, const std::vector<double>& weight) {
  const int n = int(c.size()) - 1;  // viewpoints 1..n
  const size_t full = size_t(1) << n;
  double total = 0.0;
  for (size_t j = 1; j < weight.size(); ++j) total += weight[j];
  std::vector<double> left;  // weight not yet visited after `mask`
  if (!weight.empty()) {
    left.assign(full, total);
    for (size_t mask = 1; mask < full; ++mask) {
      const int low = std::countr_zero(mask);
      left[mask] = left[mask & (mask - 1)] - weight[size_t(low) + 1];
    }
  }
  auto mult = [&](size_t mask) { return weight.empty() ? 1.0 : std::max(0.0, left[mask]); };
  // dp[mask][j]: cheapest path from 0 visiting exactly `mask`, ending at viewpoint j (0-based).
  std::vector<double> dp(full * n, kInf);
  std::vector<int> parent(full * n, -1);
  for (int j = 0; j < n; ++j) dp[(size_t(1) << j) * n + j] = c[0][j + 1] * mult(0);
  for (size_t mask = 1; mask < full; ++mask)
    for (int j = 0; j < n; ++j) {
      if (!(mask & (size_t(1) << j))) continue;
      const double here = dp[mask * n + j];
      if (here == kInf) continue;
      for (int k = 0; k < n; ++k) {
        if (mask & (size_t(1) << k)) continue;
        const size_t next = mask | (size_t(1) << k);
        const double v = here + c[j + 1][k + 1] * mult(mask);
        if (v < dp[next * n + k]) {
          dp[next * n + k] = v;
          parent[next * n + k] = j;
        }
      }
    }
  TspResult r;
  r.exact = true;
  int best = 0;
  for (int j = 1; j < n; ++j)
    if (dp[(full - 1) * n + j] < dp[(full - 1) * n + best]) best = j;
  r.cost = dp[(full - 1) * n + best];
  size_t mask = full - 1;
  for (int j = best; j != -1;) {
    r.order.push_back(j + 1);
    const int p = parent[mask * n + j];
    mask &= ~(size_t(1) << j);
    j = p;
  }
  std::reverse(r.order.begin(), r.order.end());
  return r;
}

// Improves `order` in place with 2-opt (segment reversal, cost recomputed: matrices may be
// asymmetric) and Or-opt (move a run of 1..3 nodes elsewhere) until no move helps.
template <class Objective>
void localSearch(const Objective& cost, std::vector<int>& order) {
  const int n = int(order.size());
  double best = cost(order);
  bool improved = true;
  for (int sweep = 0; improved && sweep < 100; ++sweep) {
    improved = false;
    for (int i = 0; i < n - 1; ++i)
      for (int k = i + 1; k < n; ++k) {
        std::reverse(order.begin() + i, order.begin() + k + 1);
        const double v = cost(order);
        if (v < best - 1e-12) {
          best = v;
          improved = true;
        } else {
          std::reverse(order.begin() + i, order.begin() + k + 1);
        }
      }
    for (int len = 1; len <= 3; ++len)
      for (int i = 0; i + len <= n; ++i)
        for (int j = 0; j <= n - len; ++j) {
          if (j == i) continue;
          std::vector<int> cand(order);
          std::vector<int> run(cand.begin() + i, cand.begin() + i + len);
          cand.erase(cand.begin() + i, cand.begin() + i + len);
          cand.insert(cand.begin() + j, run.begin(), run.end());
          const double v = cost(cand);
          if (v < best - 1e-12) {
            best = v;
            order.swap(cand);
            improved = true;
          }
        }
  }
}

}  // namespace

double openTourCost(const CostMatrix& c, const std::vector<int>& order) {
  double s = 0.0;
  int prev = 0;
  for (int j : order) {
    s += c[prev][j];
    prev = j;
  }
  return s;
}

double searchTourCost(const CostMatrix& c, const std::vector<double>& weight, const std::vector<int>& order) {
  double left = 0.0;
  for (int j : order) left += weight[size_t(j)];
  double s = 0.0;
  int prev = 0;
  for (int j : order) {
    s += c[prev][j] * left;
    left -= weight[size_t(j)];
    prev = j;
  }
  return s;
}

TspResult solveOpenTsp(const CostMatrix& c, int exact_limit) {
  checkMatrix(c);
  TspResult r;
  const int n = int(c.size()) - 1;
  if (n <= 0) {
    r.exact = true;
    return r;
  }
  if (n <= std::min(exact_limit, 16)) return heldKarp(c, {});
  // Nearest-neighbour construction from the start.
  std::vector<bool> used(c.size(), false);
  int cur = 0;
  for (int step = 0; step < n; ++step) {
    int best = -1;
    for (int j = 1; j <= n; ++j)
      if (!used[j] && (best < 0 || c[cur][j] < c[cur][best])) best = j;
    used[best] = true;
    r.order.push_back(best);
    cur = best;
  }
  localSearch([&](const std::vector<int>& o) { return openTourCost(c, o); }, r.order);
  r.cost = openTourCost(c, r.order);
  return r;
}

TspResult solveSearchTour(const CostMatrix& c, const std::vector<double>& weight, int exact_limit) {
  checkMatrix(c);
  if (weight.size() != c.size()) throw std::invalid_argument("search tour: one weight per node expected");
  for (double w : weight)
    if (!(w >= 0.0) || std::isinf(w)) throw std::invalid_argument("search tour weight must be finite and >= 0");
  TspResult r;
  const int n = int(c.size()) - 1;
  if (n <= 0) {
    r.exact = true;
    return r;
  }
  if (n <= std::min(exact_limit, 16)) {
    r = heldKarp(c, weight);
    r.cost = searchTourCost(c, weight, r.order);
    return r;
  }
  // Greedy construction by weight per unit of travel (the exchange-argument rule for weighted
  // completion times), then the same local search on the search objective.
  std::vector<bool> used(c.size(), false);
  int cur = 0;
  for (int step = 0; step < n; ++step) {
    int best = -1;
    double best_ratio = -1.0;
    for (int j = 1; j <= n; ++j) {
      if (used[j]) continue;
      const double ratio = weight[size_t(j)] / std::max(c[cur][j], 1e-9);
      if (ratio > best_ratio) best_ratio = ratio, best = j;
    }
    used[best] = true;
    r.order.push_back(best);
    cur = best;
  }
  localSearch([&](const std::vector<int>& o) { return searchTourCost(c, weight, o); }, r.order);
  r.cost = searchTourCost(c, weight, r.order);
  return r;
}

TspResult bruteForceOpenTsp(const CostMatrix& c) {
  checkMatrix(c);
  TspResult best;
  std::vector<int> perm(c.size() - 1);
  std::iota(perm.begin(), perm.end(), 1);
  best.cost = kInf;
  best.exact = true;
  do {
    const double v = openTourCost(c, perm);
    if (v < best.cost) {
      best.cost = v;
      best.order = perm;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  if (perm.empty()) best.cost = 0;
  return best;
}

}  // namespace ussnav
