#include "ussnav/skeleton/graph_metrics.hpp"

#include <cmath>
#include <numeric>

namespace ussnav {

std::vector<int> connectedComponents(const ConnectivityGraph& g) {
  std::vector<int> comp(g.size(), -1);
  int next = 0;
  for (size_t s = 0; s < g.size(); ++s) {
    if (comp[s] >= 0) continue;
    std::vector<int> stack{int(s)};
    comp[s] = next;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (int v : g.neighbors(u))
        if (comp[size_t(v)] < 0) {
          comp[size_t(v)] = next;
          stack.push_back(v);
        }
    }
    ++next;
  }
  return comp;
}

GraphStats graphStats(const ConnectivityGraph& g) {
  GraphStats s;
  s.nodes = int(g.size());
  s.edges = int(g.edges().size());
  for (const ScgEdge& e : g.edges()) {
    ++s.edges_by_type[size_t(e.type)];
    s.blocked_edges += e.blocked;
  }
  for (const ScgNode& n : g.nodes()) {
    s.nodes_with_obstacles += !n.obstacles.empty() || n.obstacles_overflow;
    s.gap_nodes += n.gap_seed;
    s.satellite_nodes += n.satellite;
  }
  s.queued_surfaces = int(g.queuedSurfaces());
  s.deferred_surfaces = int(g.deferredSurfaces());
  s.mean_degree = s.nodes ? 2.0 * s.edges / s.nodes : 0.0;
  const std::vector<int> comp = connectedComponents(g);
  for (int c : comp) s.components = std::max(s.components, c + 1);
  return s;
}

nlohmann::json toJson(const GraphStats& s) {
  nlohmann::json by_type = nlohmann::json::object();
  for (int t = 0; t < kEdgeTypeCount; ++t) by_type[edgeTypeName(EdgeType(t))] = s.edges_by_type[size_t(t)];
  return {{"nodes", s.nodes},
          {"edges", s.edges},
          {"edges_by_type", by_type},
          {"queued_surfaces", s.queued_surfaces},
          {"deferred_surfaces", s.deferred_surfaces},
          {"mean_degree", s.mean_degree},
          {"components", s.components},
          {"blocked_edges", s.blocked_edges},
          {"nodes_with_obstacles", s.nodes_with_obstacles},
          {"gap_nodes", s.gap_nodes},
          {"satellite_nodes", s.satellite_nodes}};
}

CoverageResult freeSpaceCoverage(const ConnectivityGraph& g, const OccupancyMap& map, double z_min,
                                 double z_max) {
  CoverageResult r;
  const double res = map.resolution();
  const Aabb w = map.window();
  if (w.empty()) return r;
  const Vec3i lo = map.keyOf(w.min + Vec3::Constant(0.5 * res));
  const Vec3i hi = map.keyOf(w.max - Vec3::Constant(0.5 * res));
  const int z0 = std::max(lo.z(), int(std::ceil(z_min / res - 0.5 - 1e-9)));
  const int z1 = std::min(hi.z(), int(std::floor(z_max / res - 0.5 + 1e-9)));
  double max_reach = 0.0;
  for (const ScgNode& n : g.nodes()) max_reach = std::max(max_reach, n.reach);
  for (int z = z0; z <= z1; ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Vec3i k(x, y, z);
        if (map.state(k) != VoxelState::Free) continue;
        ++r.free_voxels;
        const Vec3 c = map.centerOf(k);
        for (int id : g.nodesWithin(c, max_reach))
          if (g.node(id).polyhedron.contains(c, 1e-9)) {
            ++r.covered_voxels;
            break;
          }
      }
  return r;
}

}  // namespace ussnav
