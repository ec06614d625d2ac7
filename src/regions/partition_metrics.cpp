#include "ussnav/regions/partition_metrics.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace ussnav {

namespace {

// Contingency table as sorted (predicted, truth) -> count plus both marginals.
struct Contingency {
  std::map<std::pair<int, int>, long long> cells;
  std::map<int, long long> rows, cols;
};

Contingency contingency(const std::vector<int>& predicted, const std::vector<int>& truth) {
  if (predicted.size() != truth.size())
    throw std::invalid_argument("partition metrics: label vectors differ in length");
  Contingency c;
  for (size_t i = 0; i < predicted.size(); ++i) {
    ++c.cells[{predicted[i], truth[i]}];
    ++c.rows[predicted[i]];
    ++c.cols[truth[i]];
  }
  return c;
}

double pairs(long long k) { return 0.5 * static_cast<double>(k) * static_cast<double>(k - 1); }

}  // namespace

double purity(const std::vector<int>& predicted, const std::vector<int>& truth) {
  const Contingency c = contingency(predicted, truth);
  if (predicted.empty()) return 1.0;
  std::map<int, long long> best;  // predicted cluster -> largest overlap with one class
  for (const auto& [key, n] : c.cells) best[key.first] = std::max(best[key.first], n);
  long long hit = 0;
  for (const auto& [cluster, n] : best) hit += n;
  return static_cast<double>(hit) / static_cast<double>(predicted.size());
}

double adjustedRandIndex(const std::vector<int>& predicted, const std::vector<int>& truth) {
  const Contingency c = contingency(predicted, truth);
  const long long n = static_cast<long long>(predicted.size());
  if (n < 2) return 1.0;
  double index = 0.0, a = 0.0, b = 0.0;
  for (const auto& [key, k] : c.cells) index += pairs(k);
  for (const auto& [key, k] : c.rows) a += pairs(k);
  for (const auto& [key, k] : c.cols) b += pairs(k);
  const double expected = a * b / pairs(n);
  const double max_index = 0.5 * (a + b);
  // Zero denominator only when both are all-together or both all-apart: identical partitions.
  if (max_index - expected == 0.0) return 1.0;
  return (index - expected) / (max_index - expected);
}

double cpmQuality(const IndexedGraph& g, const std::vector<int>& labels, double resolution) {
  if (static_cast<int>(labels.size()) != g.size())
    throw std::invalid_argument("cpmQuality: one label per node expected");
  std::map<int, long long> sizes;
  for (int l : labels) ++sizes[l];
  double q = 0.0;
  for (const auto& e : g.edges)
    if (labels[e.u] == labels[e.v]) q += e.w;
  for (const auto& [label, k] : sizes)
    q -= 0.5 * resolution * static_cast<double>(k) * static_cast<double>(k);
  return q;
}

}  // namespace ussnav
