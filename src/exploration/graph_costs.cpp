#include "ussnav/exploration/graph_costs.hpp"

#include <queue>

namespace ussnav {

GraphDistances::GraphDistances(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& from,
                               double attach_radius)
    : g_(&g), from_(from), dist_(g.size(), kInf) {
  if (g.size() == 0) return;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  auto seed = [&](int id, double d) {
    if (d < dist_[size_t(id)]) dist_[size_t(id)] = d, pq.emplace(d, id);
  };
  const int inside = g.containingNode(from);
  if (inside >= 0) seed(inside, (g.node(inside).center - from).norm());
  for (int id : g.nodesWithin(from, attach_radius))
    if (lineOfSight(map, from, g.node(id).center, true)) seed(id, (g.node(id).center - from).norm());
  if (pq.empty()) {
    const int n = g.nearestNode(from);
    seed(n, (g.node(n).center - from).norm());
  }
  while (!pq.empty()) {
    const auto [d, u] = pq.top();
    pq.pop();
    if (d > dist_[size_t(u)]) continue;
    for (int ei : g.node(u).edges) {
      const ScgEdge& e = g.edges()[size_t(ei)];
      if (e.blocked) continue;
      const int v = e.a == u ? e.b : e.a;
      const double nd = d + e.length;
      if (nd < dist_[size_t(v)]) dist_[size_t(v)] = nd, pq.emplace(nd, v);
    }
  }
}

double GraphDistances::toPoint(const Vec3& p, int* via_node, double radius) const {
  double best = kInf;
  int arg = -1;
  if (dist_.empty()) {
    if (via_node) *via_node = -1;
    return kInf;
  }
  std::vector<int> near = g_->nodesWithin(p, radius);
  if (near.empty()) near.push_back(g_->nearestNode(p));
  for (int id : near) {
    const double d = dist_[size_t(id)] + (g_->node(id).center - p).norm();
    if (d < best) best = d, arg = id;
  }
  if (via_node) *via_node = arg;
  return best;
}

double graphDistance(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& a, const Vec3& b) {
  return GraphDistances(g, map, a).toPoint(b);
}

}  // namespace ussnav
