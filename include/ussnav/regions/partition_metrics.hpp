#pragma once
// Scores of a partition: purity and Adjusted Rand Index of predicted labels against ground
// truth (e.g. regions against rooms), and the Constant Potts Model quality that Leiden
// maximises. Labels are arbitrary ints; only equality matters. Cost: O(N log N).

#include <vector>

#include "ussnav/regions/graph_view.hpp"

namespace ussnav {

// Fraction of items whose predicted cluster's majority truth label equals their own:
// (1/N) sum_clusters max_class |cluster & class|. 1 for an empty input.
// Throws std::invalid_argument when the lengths differ.
double purity(const std::vector<int>& predicted, const std::vector<int>& truth);

// Hubert-Arabie Adjusted Rand Index: 1 for identical partitions, about 0 for random ones,
// may be negative. Inputs with fewer than two items, or where both partitions are the
// same trivial one (all together / all apart), give 1. Throws on differing lengths.
double adjustedRandIndex(const std::vector<int>& predicted, const std::vector<int>& truth);

// CPM quality sum_c (w_c - resolution * n_c^2 / 2), w_c the weight inside community c and n_c
// its node count; igraph reports this divided by the total edge weight.
// `labels` is indexed like g.ids. Throws std::invalid_argument on a size mismatch.
double cpmQuality(const IndexedGraph& g, const std::vector<int>& labels, double resolution);

}  // namespace ussnav
