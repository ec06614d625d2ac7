#include "ussnav/regions/room_graph.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "ussnav/core/random.hpp"

namespace ussnav {

RoomGraph makeRoomGrid(const RoomGridSpec& s) {
  if (s.rooms_x < 1 || s.rooms_y < 1 || s.min_side < 1 || s.max_side < s.min_side ||
      s.door_edges_max < 1)
    throw std::invalid_argument("makeRoomGrid: bad room grid spec");
  Rng rng(s.seed);
  std::vector<int> width(s.rooms_x), height(s.rooms_y);
  for (int& w : width) w = rng.uniformInt(s.min_side, s.max_side);
  for (int& h : height) h = rng.uniformInt(s.min_side, s.max_side);
  std::vector<double> x0(s.rooms_x + 1, 0.0), y0(s.rooms_y + 1, 0.0);
  for (int c = 0; c < s.rooms_x; ++c) x0[c + 1] = x0[c] + (width[c] + 1) * s.spacing;
  for (int c = 0; c < s.rooms_y; ++c) y0[c + 1] = y0[c] + (height[c] + 1) * s.spacing;

  RoomGraph out;
  auto& g = out.graph;
  // first[room] = id of node (0, 0) of that room; node (a, b) is first + b * width + a.
  std::vector<int> first(s.rooms_x * s.rooms_y);
  auto roomOf = [&](int cx, int cy) { return cy * s.rooms_x + cx; };
  auto node = [&](int cx, int cy, int a, int b) {
    return first[roomOf(cx, cy)] + b * width[cx] + a;
  };
  for (int cy = 0; cy < s.rooms_y; ++cy)
    for (int cx = 0; cx < s.rooms_x; ++cx) {
      const int r = roomOf(cx, cy);
      first[r] = static_cast<int>(g.node_ids.size());
      for (int b = 0; b < height[cy]; ++b)
        for (int a = 0; a < width[cx]; ++a) {
          g.node_ids.push_back(static_cast<int>(g.node_ids.size()));
          g.centroids.emplace_back(x0[cx] + a * s.spacing + rng.uniform(-s.jitter, s.jitter),
                                   y0[cy] + b * s.spacing + rng.uniform(-s.jitter, s.jitter),
                                   1.2);
          out.room.push_back(r);
        }
      for (int b = 0; b < height[cy]; ++b)
        for (int a = 0; a < width[cx]; ++a) {
          const int u = node(cx, cy, a, b);
          if (a + 1 < width[cx]) g.edges.emplace_back(u, node(cx, cy, a + 1, b), 1.0);
          if (b + 1 < height[cy]) g.edges.emplace_back(u, node(cx, cy, a, b + 1), 1.0);
          if (a + 1 < width[cx] && b + 1 < height[cy]) {
            if (rng.bernoulli(s.diagonal_prob))
              g.edges.emplace_back(u, node(cx, cy, a + 1, b + 1), 1.0);
            if (rng.bernoulli(s.diagonal_prob))
              g.edges.emplace_back(node(cx, cy, a + 1, b), node(cx, cy, a, b + 1), 1.0);
          }
        }
    }
  out.rooms = s.rooms_x * s.rooms_y;

  // Doors: consecutive node pairs across the shared wall; plus maybe one forced link.
  auto doorWeight = [&] { return rng.bernoulli(s.forced_door_prob) ? s.forced_weight : 1.0; };
  for (int cy = 0; cy < s.rooms_y; ++cy)
    for (int cx = 0; cx < s.rooms_x; ++cx) {
      if (cx + 1 < s.rooms_x) {
        const int h = height[cy], k = std::min(h, rng.uniformInt(1, s.door_edges_max));
        const int b0 = rng.uniformInt(0, h - k);
        for (int j = 0; j < k; ++j)
          g.edges.emplace_back(node(cx, cy, width[cx] - 1, b0 + j), node(cx + 1, cy, 0, b0 + j),
                               doorWeight());
        if (rng.bernoulli(s.extra_forced_prob)) {
          const int b = rng.uniformInt(0, h - 1);
          g.edges.emplace_back(node(cx, cy, width[cx] - 1, b), node(cx + 1, cy, 0, b),
                               s.forced_weight);
        }
      }
      if (cy + 1 < s.rooms_y) {
        const int w = width[cx], k = std::min(w, rng.uniformInt(1, s.door_edges_max));
        const int a0 = rng.uniformInt(0, w - k);
        for (int j = 0; j < k; ++j)
          g.edges.emplace_back(node(cx, cy, a0 + j, height[cy] - 1), node(cx, cy + 1, a0 + j, 0),
                               doorWeight());
        if (rng.bernoulli(s.extra_forced_prob)) {
          const int a = rng.uniformInt(0, w - 1);
          g.edges.emplace_back(node(cx, cy, a, height[cy] - 1), node(cx, cy + 1, a, 0),
                               s.forced_weight);
        }
      }
    }
  return out;
}

std::vector<int> explorationOrder(const WeightedGraphView& g, int start) {
  std::unordered_map<int, std::vector<int>> adj;
  for (const auto& [a, b, w] : g.edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  for (auto& [id, list] : adj) std::sort(list.begin(), list.end());
  std::vector<int> order;
  std::unordered_set<int> seen;
  std::deque<int> queue;
  const std::unordered_set<int> present(g.node_ids.begin(), g.node_ids.end());
  if (present.count(start)) {
    queue.push_back(start);
    seen.insert(start);
  }
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop_front();
    order.push_back(u);
    for (int v : adj[u])
      if (seen.insert(v).second) queue.push_back(v);
  }
  std::vector<int> rest;
  for (int id : g.node_ids)
    if (!seen.count(id)) rest.push_back(id);
  std::sort(rest.begin(), rest.end());
  order.insert(order.end(), rest.begin(), rest.end());
  return order;
}

WeightedGraphView inducedView(const WeightedGraphView& g, const std::vector<int>& keep_ids) {
  const std::unordered_set<int> keep(keep_ids.begin(), keep_ids.end());
  WeightedGraphView out;
  for (size_t i = 0; i < g.node_ids.size(); ++i)
    if (keep.count(g.node_ids[i])) {
      out.node_ids.push_back(g.node_ids[i]);
      out.centroids.push_back(g.centroids[i]);
    }
  for (const auto& e : g.edges)
    if (keep.count(std::get<0>(e)) && keep.count(std::get<1>(e))) out.edges.push_back(e);
  return out;
}

}  // namespace ussnav
