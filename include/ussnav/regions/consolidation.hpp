#pragma once
// Consolidation of a community partition after Leiden (paper Sec. IV-B): adjacent communities
// with dense mutual connectivity merge, and tiny communities join their most connected
// neighbour. Works on one graph and one label per node; labels come back compacted to
// 0..k-1 in order of first appearance (by dense index), so the result is deterministic.
// Cost: O(E log E) per merge round; rounds stop when nothing merges.

#include <map>
#include <utility>
#include <vector>

#include "ussnav/regions/graph_view.hpp"

namespace ussnav {

struct ConsolidationParams {
  int merge_shared_border_nodes = 4;    // merge a pair sharing MORE border nodes than this
  double border_edge_min_weight = 0.5;  // edges lighter than this never create border nodes
  int min_region_nodes = 3;             // communities with fewer nodes join a neighbour
};

// Border nodes of two adjacent communities A and B: the nodes of A with at least one edge of
// weight >= min_weight to a node of B, plus the nodes of B with such an edge to A. Each node
// counts once per pair. Key: (smaller label, larger label).
std::map<std::pair<int, int>, int> sharedBorderNodes(const IndexedGraph& g,
                                                     const std::vector<int>& labels,
                                                     double min_weight);

// Merges (1) every adjacent pair sharing more than merge_shared_border_nodes border nodes,
// repeated until no pair qualifies (merging only ever adds border nodes, so the order does
// not matter), then (2) each community below min_region_nodes into the neighbour with the
// largest total edge weight to it (ties: more edges, then smaller label), smallest first.
// Communities with no neighbour stay. Returns the number of merges.
int consolidate(const IndexedGraph& g, std::vector<int>& labels, const ConsolidationParams& p);

// Relabels to 0..k-1 in order of first appearance; returns k.
int compactLabels(std::vector<int>& labels);

}  // namespace ussnav
