#pragma once
// Input of region partitioning: an undirected weighted graph with stable node ids, as the
// Spatial Connectivity Graph hands it over (nodes = polyhedron centroids; edge weight 1 for
// standard links, epsilon for forced ones). indexGraph() validates a view and builds a CSR
// adjacency over dense indices ordered by node id, so results never depend on input order.
// Cost: O(N + E log max_degree), plus O(N log N) when the ids come unsorted.

#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

struct WeightedGraphView {
  std::vector<int> node_ids;                          // unique, stable over time
  std::vector<Vec3> centroids;                        // one per node id, same order
  std::vector<std::tuple<int, int, double>> edges;    // (id, id, weight >= 0), undirected
  // Satellite nodes (optional, a subset of node_ids): they do not enter community detection
  // and take the region of the nearest other node along the edges (see RegionPartitioner).
  std::vector<int> satellites;
};

// Builds a view from any graph: `node_fn(n)` returns pair<int, Vec3> (id, centroid) and
// `edge_fn(e)` returns tuple<int, int, double>. Plugging in another module's graph is then
//   auto view = makeGraphView(g.nodes(), nodeFn, g.edges(), edgeFn);
template <class NodeRange, class NodeFn, class EdgeRange, class EdgeFn>
WeightedGraphView makeGraphView(const NodeRange& nodes, NodeFn node_fn, const EdgeRange& edges,
                                EdgeFn edge_fn) {
  WeightedGraphView v;
  for (const auto& n : nodes) {
    auto [id, c] = node_fn(n);
    v.node_ids.push_back(id);
    v.centroids.push_back(c);
  }
  for (const auto& e : edges) v.edges.push_back(edge_fn(e));
  return v;
}

struct IndexedEdge {
  int u = 0, v = 0;  // dense indices, u < v
  double w = 0.0;
};

// A validated view. Self-loops are dropped; duplicate edges (either direction) collapse to one
// with the largest weight, because a pair linked twice (e.g. forced and standard) is as strong
// as its strongest link, not the sum.
struct IndexedGraph {
  std::vector<int> ids;              // dense index -> node id, ascending
  std::vector<Vec3> centroids;       // by dense index
  std::vector<int> offsets;          // CSR: neighbours of i are [offsets[i], offsets[i+1])
  std::vector<int> nbrs;             // ascending within each node's range
  std::vector<double> weights;
  std::vector<IndexedEdge> edges;    // sorted by (u, v)

  int size() const { return static_cast<int>(ids.size()); }
  // Dense index of a node id, -1 if absent. O(1): a flat table when the ids are compact
  // (the usual case: ids handed out by a counter), else a hash map.
  int indexOf(int id) const {
    if (!flat_.empty() || sparse_.empty()) {
      const long k = static_cast<long>(id) - base_;
      return k >= 0 && k < static_cast<long>(flat_.size()) ? flat_[k] : -1;
    }
    auto it = sparse_.find(id);
    return it == sparse_.end() ? -1 : it->second;
  }
  // Builds the id -> index lookup from `ids`; called by the constructors below.
  void buildLookup();

 private:
  long base_ = 0;
  std::vector<int> flat_;
  std::unordered_map<int, int> sparse_;
};

// Throws InputError(source, field, what) for mismatched sizes, duplicate node ids, edges to
// unknown ids, and negative or non-finite weights or centroids.
IndexedGraph indexGraph(const WeightedGraphView& g, const std::string& source = "graph view");

// The subgraph induced by `keep` (dense indices of `g`, strictly ascending), indexed anew.
// O(sum of degrees of kept nodes).
IndexedGraph inducedSubgraph(const IndexedGraph& g, const std::vector<int>& keep);

}  // namespace ussnav
