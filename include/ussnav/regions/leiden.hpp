#pragma once
// Leiden community detection (igraph_community_leiden) with the Constant Potts Model: node
// weights 1, quality Q = (1/2m) sum_ij (A_ij - resolution) [c_i == c_j], so two groups of a and
// b nodes stay apart while the weight between them is below resolution * a * b.
// Deterministic: igraph's global RNG is re-seeded before every call, so calls must not run
// concurrently from several threads. Cost: near linear in edges per iteration.

#include <cstdint>
#include <vector>

#include "ussnav/regions/graph_view.hpp"

namespace ussnav {

// Cap on "until stable": Leiden iterations only improve the partition, so on our graphs a
// handful suffice; the cap bounds the time if randomness keeps moving tied nodes around.
constexpr int kMaxLeidenIterations = 50;

struct LeidenParams {
  double resolution = 0.02;
  double beta = 0.01;
  int iterations = -1;  // > 0: exactly this many; < 0: until the partition stops changing
  uint64_t seed = 1;
};

struct LeidenResult {
  std::vector<int> membership;  // community per node, 0..communities-1
  int communities = 0;
  double quality = 0.0;         // igraph's CPM quality of `membership`
};

// Partitions nodes 0..n-1 linked by `edges` (u != v, weight >= 0). With `initial` (size n,
// any non-negative labels) Leiden starts from that partition instead of singletons.
// Throws std::runtime_error if igraph reports an error, std::invalid_argument on bad input
// (including iterations == 0).
LeidenResult leiden(int n, const std::vector<IndexedEdge>& edges, const LeidenParams& params,
                     const std::vector<int>* initial = nullptr);

}  // namespace ussnav
