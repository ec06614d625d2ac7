#pragma once
// Synthetic connectivity graphs shaped like the Spatial Connectivity Graph of a building, for
// tests and benchmarks of region partitioning: a grid of rectangular rooms of jittered nodes
// about 1 m apart (4-neighbour links plus some diagonals, weight 1), neighbouring rooms joined
// by doors of 1-2 edges (weight 1 or forced epsilon) and extra forced links. Ground truth is
// each node's room. Deterministic in the seed. Cost: O(nodes).

#include <cstdint>
#include <vector>

#include "ussnav/regions/graph_view.hpp"

namespace ussnav {

struct RoomGridSpec {
  int rooms_x = 3, rooms_y = 3;   // rooms per row and per column
  int min_side = 3, max_side = 6; // nodes per room side; each column / row of rooms draws one
  double spacing = 1.0;           // m between neighbouring nodes; doors span 2 * spacing
  double jitter = 0.15;           // m, uniform noise on node positions
  double diagonal_prob = 0.5;     // probability of each diagonal link inside a room
  int door_edges_max = 2;         // each neighbouring pair gets 1..door_edges_max door edges
  double forced_door_prob = 0.3;  // a door edge is forced (weight forced_weight)
  double extra_forced_prob = 0.2; // a neighbouring pair also gets one forced link elsewhere
  double forced_weight = 0.01;    // epsilon (paper)
  uint64_t seed = 1;
};

struct RoomGraph {
  WeightedGraphView graph;  // node ids 0..N-1 in room order
  std::vector<int> room;    // ground-truth room per node, same order as graph.node_ids
  int rooms = 0;
};

RoomGraph makeRoomGrid(const RoomGridSpec& spec);

// Breadth-first order from node `start` (neighbours in ascending id), as an explorer would
// reveal the graph; nodes not reachable from `start` follow in ascending id.
std::vector<int> explorationOrder(const WeightedGraphView& g, int start);

// The graph restricted to `keep_ids` (any order; unknown ids are ignored).
WeightedGraphView inducedView(const WeightedGraphView& g, const std::vector<int>& keep_ids);

}  // namespace ussnav
