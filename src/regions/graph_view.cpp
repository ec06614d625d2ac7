#include "ussnav/regions/graph_view.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

#include "ussnav/core/error.hpp"

namespace ussnav {

namespace {

// CSR from `out.edges` (sorted by (u, v)): each node's neighbours come out ascending, since
// the lower neighbours are filled first (edges (w, i), w < i, precede edges (i, v)).
void buildAdjacency(IndexedGraph& out) {
  const int n = out.size();
  out.offsets.assign(n + 1, 0);
  for (const auto& e : out.edges) {
    ++out.offsets[e.u + 1];
    ++out.offsets[e.v + 1];
  }
  for (int i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
  out.nbrs.resize(out.offsets[n]);
  out.weights.resize(out.offsets[n]);
  std::vector<int> fill(out.offsets.begin(), out.offsets.end() - 1);
  for (const auto& e : out.edges) {
    out.nbrs[fill[e.u]] = e.v;
    out.weights[fill[e.u]++] = e.w;
    out.nbrs[fill[e.v]] = e.u;
    out.weights[fill[e.v]++] = e.w;
  }
}

}  // namespace

void IndexedGraph::buildLookup() {
  flat_.clear();
  sparse_.clear();
  base_ = 0;
  if (ids.empty()) return;
  const long lo = ids.front(), hi = ids.back();  // ids are ascending
  if (hi - lo < 4L * static_cast<long>(ids.size()) + 64) {
    base_ = lo;
    flat_.assign(static_cast<size_t>(hi - lo + 1), -1);
    for (int i = 0; i < size(); ++i) flat_[static_cast<size_t>(ids[i] - lo)] = i;
  } else {
    sparse_.reserve(ids.size());
    for (int i = 0; i < size(); ++i) sparse_.emplace(ids[i], i);
  }
}

IndexedGraph indexGraph(const WeightedGraphView& g, const std::string& source) {
  if (g.centroids.size() != g.node_ids.size())
    throw InputError(source, "centroids",
                     "expected one centroid per node id (" + std::to_string(g.node_ids.size()) +
                         "), got " + std::to_string(g.centroids.size()));
  const int n = static_cast<int>(g.node_ids.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (!std::is_sorted(g.node_ids.begin(), g.node_ids.end()))
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return g.node_ids[a] < g.node_ids[b]; });

  IndexedGraph out;
  out.ids.resize(n);
  out.centroids.resize(n);
  for (int i = 0; i < n; ++i) {
    const int src = order[i];
    out.ids[i] = g.node_ids[src];
    if (i > 0 && out.ids[i] == out.ids[i - 1])
      throw InputError(source, "node_ids", "duplicate node id " + std::to_string(out.ids[i]));
    out.centroids[i] = g.centroids[src];
    if (!out.centroids[i].allFinite())
      throw InputError(source, "centroids[" + std::to_string(src) + "]",
                       "expected finite coordinates");
  }
  out.buildLookup();

  // Bucket by the lower endpoint (counting sort), then sort each short row by the other.
  std::vector<int> row(n + 1, 0);
  std::vector<IndexedEdge> raw(g.edges.size());
  size_t kept = 0;
  for (size_t k = 0; k < g.edges.size(); ++k) {
    const auto& [a, b, w] = g.edges[k];
    auto field = [k] { return "edges[" + std::to_string(k) + "]"; };
    const int ia = out.indexOf(a), ib = out.indexOf(b);
    if (ia < 0 || ib < 0)
      throw InputError(source, field(),
                       "node id " + std::to_string(ia < 0 ? a : b) + " is not in node_ids");
    if (!std::isfinite(w) || w < 0.0)
      throw InputError(source, field(), "expected a finite weight >= 0");
    if (ia == ib) continue;
    raw[kept++] = {std::min(ia, ib), std::max(ia, ib), w};
    ++row[std::min(ia, ib) + 1];
  }
  for (int i = 0; i < n; ++i) row[i + 1] += row[i];
  std::vector<IndexedEdge> bucketed(kept);
  std::vector<int> fill(row.begin(), row.end() - 1);
  for (size_t k = 0; k < kept; ++k) bucketed[fill[raw[k].u]++] = raw[k];
  out.edges.reserve(kept);
  for (int i = 0; i < n; ++i) {
    auto first = bucketed.begin() + row[i], last = bucketed.begin() + row[i + 1];
    std::sort(first, last, [](const IndexedEdge& x, const IndexedEdge& y) {
      return x.v != y.v ? x.v < y.v : x.w > y.w;
    });
    for (auto it = first; it != last; ++it)  // the first of each v run has the largest weight
      if (it == first || std::prev(it)->v != it->v) out.edges.push_back(*it);
  }
  buildAdjacency(out);
  return out;
}

IndexedGraph inducedSubgraph(const IndexedGraph& g, const std::vector<int>& keep) {
  IndexedGraph out;
  const int k = static_cast<int>(keep.size());
  std::vector<int> local(g.size(), -1);
  out.ids.resize(k);
  out.centroids.resize(k);
  for (int i = 0; i < k; ++i) {
    local[keep[i]] = i;
    out.ids[i] = g.ids[keep[i]];
    out.centroids[i] = g.centroids[keep[i]];
  }
  out.buildLookup();
  // keep is ascending and each CSR row is ascending, so edges come out sorted by (u, v).
  for (int i = 0; i < k; ++i) {
    const int gu = keep[i];
    for (int a = g.offsets[gu]; a < g.offsets[gu + 1]; ++a) {
      const int lv = local[g.nbrs[a]];
      if (lv > i) out.edges.push_back({i, lv, g.weights[a]});
    }
  }
  buildAdjacency(out);
  return out;
}

}  // namespace ussnav
