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
  // A pair merges only through an opening at least this wide (crossingOpening); 0: any.
  double merge_min_opening_m = 0.0;
};

// Border nodes of two adjacent communities A and B: the nodes of A with at least one edge of
// weight >= min_weight to a node of B, plus the nodes of B with such an edge to A. Each node
// counts once per pair. Key: (smaller label, larger label).
std::map<std::pair<int, int>, int> sharedBorderNodes(const IndexedGraph& g,
                                                     const std::vector<int>& labels,
                                                     double min_weight);

// The width of the opening two communities meet through, measured on the crossing edges (weight
// >= min_weight, one end in each) as straight segments between the node centroids, in the
// horizontal plane: for each of 12 directions (every 15 degrees) and each vertical plane across
// it (0.1 m steps) that cuts at least 3/4 of the segments, the points where the cut segments
// cross it, split into groups at gaps wider than 2 m (two doors in one wall are two openings);
// the widest group's extent. The opening is the least such extent over all planes: the
// narrowest cross-section nearly all crossing edges pass through. A door gives at most its own
// width less the polyhedra's distance from its jambs; two patches of one open space give the
// length of their shared border. When no plane cuts 3/4 of them (a bent border), the extent of
// their midpoints. 0 when there are no crossing edges.
double crossingOpening(const IndexedGraph& g, const std::vector<int>& labels, int a, int b, double min_weight);

// Merges (1) every adjacent pair sharing more than merge_shared_border_nodes border nodes and,
// when merge_min_opening_m > 0, meeting through an opening at least that wide,
// repeated until no pair qualifies (merging only ever adds border nodes, so the order does
// not matter), then (2) each community below min_region_nodes into the neighbour with the
// largest total edge weight to it (ties: more edges, then smaller label), smallest first.
// Communities with no neighbour stay. Returns the number of merges.
int consolidate(const IndexedGraph& g, std::vector<int>& labels, const ConsolidationParams& p);

// Relabels to 0..k-1 in order of first appearance; returns k.
int compactLabels(std::vector<int>& labels);

}  // namespace ussnav
