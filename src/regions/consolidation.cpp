#include "ussnav/regions/consolidation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace ussnav {

namespace {

int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Rounds of "merge every pair above the threshold" until a fixpoint.
int mergeDenseBorders(const IndexedGraph& g, std::vector<int>& labels,
                      const ConsolidationParams& p) {
  int merges = 0;
  for (;;) {
    const int k = compactLabels(labels);
    const auto shared = sharedBorderNodes(g, labels, p.border_edge_min_weight);
    std::vector<int> parent(k);
    std::iota(parent.begin(), parent.end(), 0);
    int round = 0;
    for (const auto& [pair, count] : shared) {
      if (count <= p.merge_shared_border_nodes) continue;
      const int a = findRoot(parent, pair.first), b = findRoot(parent, pair.second);
      if (a == b) continue;
      if (p.merge_min_opening_m > 0.0 &&
          crossingOpening(g, labels, pair.first, pair.second, p.border_edge_min_weight) < p.merge_min_opening_m)
        continue;
      parent[std::max(a, b)] = std::min(a, b);
      ++round;
    }
    if (round == 0) return merges;
    merges += round;
    for (int& l : labels) l = findRoot(parent, l);
  }
}

int absorbSmall(const IndexedGraph& g, std::vector<int>& labels, const ConsolidationParams& p) {
  int merges = 0;
  for (bool again = true; again;) {
    again = false;
    const int k = compactLabels(labels);
    std::vector<std::vector<int>> members(k);
    for (int i = 0; i < g.size(); ++i) members[labels[i]].push_back(i);
    std::vector<int> order;
    for (int c = 0; c < k; ++c)
      if (static_cast<int>(members[c].size()) < p.min_region_nodes) order.push_back(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return std::make_pair(members[a].size(), a) < std::make_pair(members[b].size(), b);
    });
    for (int c : order) {
      if (members[c].empty() || static_cast<int>(members[c].size()) >= p.min_region_nodes)
        continue;
      std::unordered_map<int, std::pair<double, int>> link;  // label -> (weight, edges)
      for (int u : members[c])
        for (int a = g.offsets[u]; a < g.offsets[u + 1]; ++a) {
          const int l = labels[g.nbrs[a]];
          if (l == c) continue;
          auto& w = link[l];
          w.first += g.weights[a];
          ++w.second;
        }
      if (link.empty()) continue;
      int best = -1;
      std::tuple<double, int, int> best_key{-1.0, 0, 0};
      for (const auto& [l, w] : link) {
        const std::tuple<double, int, int> key{w.first, w.second, -l};
        if (best < 0 || key > best_key) {
          best = l;
          best_key = key;
        }
      }
      for (int u : members[c]) labels[u] = best;
      members[best].insert(members[best].end(), members[c].begin(), members[c].end());
      members[c].clear();
      ++merges;
      again = true;
    }
  }
  return merges;
}

}  // namespace

int compactLabels(std::vector<int>& labels) {
  std::unordered_map<int, int> remap;
  for (int& l : labels) {
    auto [it, inserted] = remap.emplace(l, static_cast<int>(remap.size()));
    l = it->second;
  }
  return static_cast<int>(remap.size());
}

std::map<std::pair<int, int>, int> sharedBorderNodes(const IndexedGraph& g,
                                                     const std::vector<int>& labels,
                                                     double min_weight) {
  if (static_cast<int>(labels.size()) != g.size())
    throw std::invalid_argument("sharedBorderNodes: one label per node expected");
  // (label of this node, label of the other side, node): sorted and made unique so a node
  // with several edges into the same community counts once.
  std::vector<std::tuple<int, int, int>> border;
  for (const auto& e : g.edges) {
    if (e.w < min_weight || labels[e.u] == labels[e.v]) continue;
    border.emplace_back(labels[e.u], labels[e.v], e.u);
    border.emplace_back(labels[e.v], labels[e.u], e.v);
  }
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());
  std::map<std::pair<int, int>, int> out;
  for (const auto& [a, b, node] : border) ++out[{std::min(a, b), std::max(a, b)}];
  return out;
}

double crossingOpening(const IndexedGraph& g, const std::vector<int>& labels, int a, int b, double min_weight) {
  if (static_cast<int>(labels.size()) != g.size())
    throw std::invalid_argument("crossingOpening: one label per node expected");
  struct Segment {
    double px, py, qx, qy;
  };
  std::vector<Segment> seg;
  for (const auto& e : g.edges) {
    if (e.w < min_weight) continue;
    const int lu = labels[e.u], lv = labels[e.v];
    if (!((lu == a && lv == b) || (lu == b && lv == a))) continue;
    const Vec3& p = g.centroids[e.u];
    const Vec3& q = g.centroids[e.v];
    seg.push_back({p.x(), p.y(), q.x(), q.y()});
  }
  if (seg.empty()) return 0.0;
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kStep = 0.1;       // m between the planes tried along a direction
  constexpr double kGroupGap = 2.0;   // m: crossing points further apart are two openings
  const size_t need = (3 * seg.size() + 3) / 4;
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> lateral;
  for (int k = 0; k < 12; ++k) {
    const double th = k * kPi / 12.0, dx = std::cos(th), dy = std::sin(th);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Segment& s : seg) {
      lo = std::min({lo, s.px * dx + s.py * dy, s.qx * dx + s.qy * dy});
      hi = std::max({hi, s.px * dx + s.py * dy, s.qx * dx + s.qy * dy});
    }
    for (double o = lo; o <= hi + 1e-9; o += kStep) {
      lateral.clear();
      for (const Segment& s : seg) {
        const double sp = s.px * dx + s.py * dy, sq = s.qx * dx + s.qy * dy;
        if (o < std::min(sp, sq) || o > std::max(sp, sq)) continue;
        const double t = sq != sp ? (o - sp) / (sq - sp) : 0.5;
        lateral.push_back(-(s.px + t * (s.qx - s.px)) * dy + (s.py + t * (s.qy - s.py)) * dx);
      }
      if (lateral.size() < need) continue;
      std::sort(lateral.begin(), lateral.end());
      double widest = 0.0;
      for (size_t i = 0, start = 0; i < lateral.size(); ++i)
        if (i + 1 == lateral.size() || lateral[i + 1] - lateral[i] > kGroupGap) {
          widest = std::max(widest, lateral[i] - lateral[start]);
          start = i + 1;
        }
      best = std::min(best, widest);
    }
  }
  if (std::isfinite(best)) return best;
  // No plane cuts 3/4 of them (a border that bends, segments side by side along it): no single
  // opening; the extent of their midpoints.
  double x0 = best, y0 = best, x1 = -best, y1 = -best;
  for (const Segment& s : seg) {
    const double mx = 0.5 * (s.px + s.qx), my = 0.5 * (s.py + s.qy);
    x0 = std::min(x0, mx), x1 = std::max(x1, mx), y0 = std::min(y0, my), y1 = std::max(y1, my);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

int consolidate(const IndexedGraph& g, std::vector<int>& labels, const ConsolidationParams& p) {
  if (static_cast<int>(labels.size()) != g.size())
    throw std::invalid_argument("consolidate: one label per node expected");
  int merges = mergeDenseBorders(g, labels, p);
  merges += absorbSmall(g, labels, p);
  compactLabels(labels);
  return merges;
}

}  // namespace ussnav
