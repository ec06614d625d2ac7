// ConnectivityGraph: storage, queries and the spatial hash. The update loop (Algorithm 1) is in
// connectivity_update.cpp.
#include "ussnav/skeleton/connectivity_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "ussnav/skeleton/grid_path.hpp"
#include "ussnav/skeleton/sphere_sampler.hpp"

namespace ussnav {

const char* edgeTypeName(EdgeType t) {
  switch (t) {
    case EdgeType::Kinematic: return "kinematic";
    case EdgeType::Overlap: return "overlap";
    case EdgeType::Visible: return "visible";
    case EdgeType::Loop: return "loop";
  }
  return "?";
}

ConnectivityGraph::ConnectivityGraph(const SkeletonConfig& cfg)
    : cfg_(cfg), directions_(fibonacciSphere(cfg.sphere_samples)) {
  // Cells of about a polyhedron's diameter keep radius queries at a few dozen cells.
  cell_size_ = std::max(0.5, 2.0 * cfg_.max_radius);
}

int ConnectivityGraph::edgeBetween(int a, int b) const {
  if (a < 0 || b < 0 || a >= int(nodes_.size()) || b >= int(nodes_.size())) return -1;
  const ScgNode& n = nodes_[size_t(nodes_[size_t(a)].edges.size() <= nodes_[size_t(b)].edges.size() ? a : b)];
  const int other = n.id == a ? b : a;
  for (int e : n.edges) {
    const ScgEdge& ed = edges_[size_t(e)];
    if (ed.a == other || ed.b == other) return e;
  }
  return -1;
}

std::vector<int> ConnectivityGraph::neighbors(int id) const {
  std::vector<int> out;
  for (int e : nodes_[size_t(id)].edges) {
    const ScgEdge& ed = edges_[size_t(e)];
    out.push_back(ed.a == id ? ed.b : ed.a);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Vec3> ConnectivityGraph::edgePolyline(int edge) const {
  const ScgEdge& e = edges_[size_t(edge)];
  std::vector<Vec3> pts{nodes_[size_t(e.a)].center};
  pts.insert(pts.end(), e.via.begin(), e.via.end());
  pts.push_back(nodes_[size_t(e.b)].center);
  return pts;
}

std::vector<int> ConnectivityGraph::nodesCreatedSince(double t) const {
  std::vector<int> out;
  for (const ScgNode& n : nodes_)
    if (n.created_time > t) out.push_back(n.id);
  return out;
}

Vec3i ConnectivityGraph::cellOf(const Vec3& p) const {
  return Vec3i(int(std::floor(p.x() / cell_size_)), int(std::floor(p.y() / cell_size_)),
               int(std::floor(p.z() / cell_size_)));
}

int64_t ConnectivityGraph::cellKey(const Vec3i& c) const {
  // 21 bits per axis: +-1M cells of >= 0.5 m, far beyond any building.
  const auto u = [](int v) { return int64_t(uint32_t(v + (1 << 20)) & 0x1FFFFF); };
  return (u(c.x()) << 42) | (u(c.y()) << 21) | u(c.z());
}

void ConnectivityGraph::indexNode(int id) {
  cells_[cellKey(cellOf(nodes_[size_t(id)].center))].push_back(id);
  max_reach_ = std::max(max_reach_, nodes_[size_t(id)].reach);
}

std::vector<int> ConnectivityGraph::nodesWithin(const Vec3& p, double r) const {
  std::vector<std::pair<double, int>> found;
  if (r >= 0 && !nodes_.empty()) {
    const Vec3i lo = cellOf(p - Vec3::Constant(r)), hi = cellOf(p + Vec3::Constant(r));
    const double r2 = r * r;
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int x = lo.x(); x <= hi.x(); ++x) {
          const auto it = cells_.find(cellKey(Vec3i(x, y, z)));
          if (it == cells_.end()) continue;
          for (int id : it->second) {
            const double d2 = (nodes_[size_t(id)].center - p).squaredNorm();
            if (d2 <= r2) found.emplace_back(d2, id);
          }
        }
  }
  std::sort(found.begin(), found.end());
  std::vector<int> out;
  out.reserve(found.size());
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

bool ConnectivityGraph::hasCenterWithin(const Vec3& p, double r, bool core_only) const {
  const Vec3i lo = cellOf(p - Vec3::Constant(r)), hi = cellOf(p + Vec3::Constant(r));
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const auto it = cells_.find(cellKey(Vec3i(x, y, z)));
        if (it == cells_.end()) continue;
        for (int id : it->second)
          if ((nodes_[size_t(id)].center - p).squaredNorm() <= r * r &&
              !(core_only && nodes_[size_t(id)].satellite))
            return true;
      }
  return false;
}

int ConnectivityGraph::nearestNode(const Vec3& p) const {
  if (nodes_.empty()) return -1;
  // Grow the search radius; fall back to a scan when the graph is far away.
  for (double r = cell_size_; r <= 16 * cell_size_; r *= 2) {
    const std::vector<int> near = nodesWithin(p, r);
    if (!near.empty()) return near.front();
  }
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (const ScgNode& n : nodes_) {
    const double d = (n.center - p).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = n.id;
    }
  }
  return best;
}

int ConnectivityGraph::containingNode(const Vec3& p, bool core_only) const {
  int best = -1;
  for (int id : nodesWithin(p, max_reach_)) {
    const ScgNode& n = nodes_[size_t(id)];
    if (core_only && n.satellite) continue;
    if ((n.center - p).norm() <= n.reach + 1e-9 && n.polyhedron.contains(p) && (best < 0 || id < best))
      best = id;
  }
  return best;
}

int ConnectivityGraph::addEdge(int a, int b, EdgeType type, double weight, std::vector<Vec3> via) {
  ScgEdge e;
  e.a = a;
  e.b = b;
  e.type = type;
  e.weight = weight;
  e.via = std::move(via);
  const int id = int(edges_.size());
  edges_.push_back(std::move(e));
  edges_.back().length = polylineLength(edgePolyline(id));
  max_edge_length_ = std::max(max_edge_length_, edges_.back().length);
  nodes_[size_t(a)].edges.push_back(id);
  nodes_[size_t(b)].edges.push_back(id);
  return id;
}

std::unordered_map<int, double> ConnectivityGraph::graphDistances(int from, double limit,
                                                                  bool core_only) const {
  std::unordered_map<int, double> dist{{from, 0.0}};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  open.push({0.0, from});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    for (int e : nodes_[size_t(u)].edges) {
      const ScgEdge& ed = edges_[size_t(e)];
      const int v = ed.a == u ? ed.b : ed.a;
      if (core_only && nodes_[size_t(v)].satellite) continue;
      const double nd = d + ed.length;
      if (nd > limit) continue;
      const auto it = dist.find(v);
      if (it == dist.end() || nd < it->second) {
        dist[v] = nd;
        open.push({nd, v});
      }
    }
  }
  return dist;
}

}  // namespace ussnav
