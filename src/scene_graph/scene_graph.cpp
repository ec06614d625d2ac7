#include "ussnav/scene_graph/scene_graph.hpp"

#include <algorithm>
#include <map>

#include "ussnav/pipeline/mapper.hpp"

namespace ussnav {
namespace {

template <class T>
int indexById(const std::vector<T>& v, int id) {
  auto it = std::lower_bound(v.begin(), v.end(), id, [](const T& x, int i) { return x.id < i; });
  return it != v.end() && it->id == id ? int(it - v.begin()) : -1;
}

std::vector<Vec3> hullVertices(const Polyhedron& p) {
  std::vector<char> on_hull(p.points.size(), 0);
  for (const auto& f : p.faces)
    for (int i : f) on_hull[size_t(i)] = 1;
  std::vector<Vec3> out;
  for (size_t i = 0; i < p.points.size(); ++i)
    if (on_hull[i]) out.push_back(p.points[i]);
  return out;
}

}  // namespace

int SceneGraph::nodeIndex(int id) const { return indexById(nodes, id); }
int SceneGraph::regionIndex(int id) const { return indexById(regions, id); }

SceneGraph buildSceneGraph(const Mapper& m, double time, const std::string& source,
                           const SceneGraphBuildOptions& opt) {
  SceneGraph g;
  g.source = source;
  g.time = time;
  const ConnectivityGraph& cg = m.graph();
  g.nodes.reserve(cg.size());
  for (const ScgNode& n : cg.nodes())
    g.nodes.push_back({n.id, n.center, n.reach, hullVertices(n.polyhedron), n.created_time});
  g.edges.reserve(cg.edges().size());
  for (const ScgEdge& e : cg.edges()) g.edges.push_back({e.a, e.b, edgeTypeName(e.type), e.weight, e.blocked});
  for (const auto& [id, r] : m.regions().regions())
    g.regions.push_back({id, r.nodes, "", "", r.centroid, r.adjacent});
  if (const ObjectLayer* ol = m.objects())
    for (const MappedObject& o : ol->objects()) {
      if (opt.confirmed_objects_only && !o.confirmed) continue;
      g.objects.push_back({o.id, o.label, o.centroid, o.box.min, o.box.max, o.n_observations, o.node_id,
                           o.region_id});
    }
  std::sort(g.objects.begin(), g.objects.end(), [](const SgObject& a, const SgObject& b) { return a.id < b.id; });
  const CoverageMask& cov = m.coverage();
  g.coverage.cell_size = double(cov.cellVoxels().x()) * m.grid().resolution();
  g.coverage.cell_height = double(cov.cellVoxels().z()) * m.grid().resolution();
  g.coverage.visited_cells = int64_t(cov.visitedCount());
  g.coverage.explored_area_m2 = cov.exploredArea();
  for (const CoverageCellInfo& c : cov.allocatedCells())
    if (c.visited) g.coverage.visited.push_back(c.cell);
  std::sort(g.coverage.visited.begin(), g.coverage.visited.end(), [](const Vec3i& a, const Vec3i& b) {
    return std::tie(a.z(), a.y(), a.x()) < std::tie(b.z(), b.y(), b.x());
  });
  return g;
}

SceneGraphCounts countLayers(const SceneGraph& g) {
  SceneGraphCounts c;
  c.nodes = int(g.nodes.size());
  c.edges = int(g.edges.size());
  c.regions = int(g.regions.size());
  c.objects = int(g.objects.size());
  for (const auto& r : g.regions) c.labelled_regions += r.label.empty() ? 0 : 1;
  for (int t = 0; t < kEdgeTypeCount; ++t) c.edges_by_type.emplace_back(edgeTypeName(EdgeType(t)), 0);
  for (const auto& e : g.edges)
    for (auto& [name, n] : c.edges_by_type)
      if (name == e.type) ++n;
  std::map<std::string, int> labels;
  for (const auto& o : g.objects) ++labels[o.label];
  c.objects_by_label.assign(labels.begin(), labels.end());
  std::stable_sort(c.objects_by_label.begin(), c.objects_by_label.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  return c;
}

}  // namespace ussnav
