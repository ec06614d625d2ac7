#include "ussnav/regions/assignment.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ussnav {

namespace {

// Minimum-cost assignment of n rows to m >= n columns; cost is 1-based (row 0 / col 0 unused
// sentinels), the classic potential-based formulation. Returns col -> row (0 = free).
std::vector<int> hungarianMin(const std::vector<std::vector<double>>& cost, int n, int m) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> p(m + 1, 0), way(m + 1, 0);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<char> used(m + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = cost[i0][j] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  return p;
}

}  // namespace

std::vector<int> maxScoreAssignment(const std::vector<std::vector<double>>& score) {
  const int rows = static_cast<int>(score.size());
  if (rows == 0) return {};
  const int cols = static_cast<int>(score[0].size());
  for (const auto& r : score) {
    if (static_cast<int>(r.size()) != cols)
      throw std::invalid_argument("maxScoreAssignment: ragged score matrix");
    for (double s : r)
      if (!std::isfinite(s)) throw std::invalid_argument("maxScoreAssignment: non-finite score");
  }
  std::vector<int> result(rows, -1);
  if (cols == 0) return result;
  // The solver wants rows <= cols: transpose when needed. Cost = -score.
  const bool transpose = rows > cols;
  const int n = transpose ? cols : rows, m = transpose ? rows : cols;
  std::vector<std::vector<double>> cost(n + 1, std::vector<double>(m + 1, 0.0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) cost[i + 1][j + 1] = transpose ? -score[j][i] : -score[i][j];
  const std::vector<int> p = hungarianMin(cost, n, m);
  for (int j = 1; j <= m; ++j) {
    if (p[j] == 0) continue;
    if (transpose)
      result[j - 1] = p[j] - 1;
    else
      result[p[j] - 1] = j - 1;
  }
  return result;
}

}  // namespace ussnav
