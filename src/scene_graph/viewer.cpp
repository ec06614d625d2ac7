// The scene graph in a web page (see viewer.hpp). The page itself is src/scene_graph/viewer.html,
// compiled in by CMake as a raw string; this file only fills in its data.

#include "ussnav/scene_graph/viewer.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/skeleton/graph_drawing.hpp"

namespace ussnav {
namespace {

constexpr const char* kPage =
#include "ussnav/viewer_html.inc"
    ;
constexpr const char* kDataMark = "__USSNAV_VIEWER_DATA__";

double cm(double x) { return std::round(x * 100.0) / 100.0; }

nlohmann::json xyz(const Vec3& p) { return {cm(p.x()), cm(p.y()), cm(p.z())}; }

// A polygon as a flat [x0, y0, x1, y1, ...] list.
nlohmann::json flat(const std::vector<Vec2>& poly) {
  nlohmann::json a = nlohmann::json::array();
  for (const Vec2& p : poly) a.push_back(cm(p.x())), a.push_back(cm(p.y()));
  return a;
}

std::string hex(const Rgb& c) {
  char s[8];
  std::snprintf(s, sizeof s, "#%02x%02x%02x", c[0], c[1], c[2]);
  return s;
}

}  // namespace

nlohmann::json viewerData(const SceneGraph& g, const ViewerOverlay& ov) {
  nlohmann::json j;
  j["format"] = "ussnav-viewer";
  j["version"] = 1;
  j["title"] = ov.title.empty() ? g.source : ov.title;
  j["source"] = g.source;
  j["time"] = g.time;

  std::vector<int> region_of(g.nodes.size(), -1);
  for (const SgRegion& r : g.regions)
    for (int id : r.nodes)
      if (const int i = g.nodeIndex(id); i >= 0) region_of[size_t(i)] = r.id;
  nlohmann::json nodes = nlohmann::json::array();
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const SgNode& n = g.nodes[i];
    std::vector<Vec2> pts;
    pts.reserve(n.hull.size());
    for (const Vec3& v : n.hull) pts.emplace_back(v.x(), v.y());
    nodes.push_back({{"id", n.id}, {"region", region_of[i]}, {"c", xyz(n.centroid)}, {"r", cm(n.radius)},
                     {"poly", flat(convexOutline2d(pts))}});
  }
  j["nodes"] = std::move(nodes);

  nlohmann::json types = nlohmann::json::array();
  for (int t = 0; t < kEdgeTypeCount; ++t)
    types.push_back({{"name", edgeTypeName(EdgeType(t))}, {"color", hex(edgeTypeColor(EdgeType(t)))}});
  j["edge_types"] = std::move(types);
  nlohmann::json edges = nlohmann::json::array();
  for (const SgEdge& e : g.edges) {
    int type = -1;
    for (int t = 0; t < kEdgeTypeCount; ++t)
      if (e.type == edgeTypeName(EdgeType(t))) type = t;
    edges.push_back({e.a, e.b, type, e.blocked ? 1 : 0});
  }
  j["edges"] = std::move(edges);

  nlohmann::json regions = nlohmann::json::array();
  for (const SgRegion& r : g.regions)
    regions.push_back({{"id", r.id}, {"label", r.label}, {"description", r.description}, {"c", xyz(r.centroid)},
                       {"adjacent", r.adjacent}, {"nodes", r.nodes.size()}, {"color", hex(paletteColor(r.id))}});
  j["regions"] = std::move(regions);

  nlohmann::json objects = nlohmann::json::array();
  for (const SgObject& o : g.objects)
    objects.push_back({{"id", o.id}, {"label", o.label}, {"c", xyz(o.centroid)}, {"min", xyz(o.bbox_min)},
                       {"max", xyz(o.bbox_max)}, {"n", o.n_observations}, {"node", o.node_id}, {"region", o.region_id}});
  j["objects"] = std::move(objects);

  // Coverage: the visited cells' x-y columns (the page draws one square per column).
  std::set<std::pair<int, int>> columns;
  for (const Vec3i& c : g.coverage.visited) columns.insert({c.x(), c.y()});
  nlohmann::json cols = nlohmann::json::array();
  for (const auto& [i, k] : columns) cols.push_back({i, k});
  j["coverage"] = {{"cell", g.coverage.cell_size}, {"columns", std::move(cols)},
                   {"explored_m2", cm(g.coverage.explored_area_m2)}};

  nlohmann::json rooms = nlohmann::json::array();
  for (const auto& r : ov.rooms) rooms.push_back({{"id", r.id}, {"type", r.type}, {"poly", flat(r.polygon)}});
  nlohmann::json walls = nlohmann::json::array();
  for (const auto& [a, b] : ov.walls) walls.push_back({cm(a.x()), cm(a.y()), cm(b.x()), cm(b.y())});
  nlohmann::json goals = nlohmann::json::array();
  for (const auto& gl : ov.goals) goals.push_back({{"id", gl.id}, {"category", gl.category}, {"poly", flat(gl.footprint)}});
  nlohmann::json traj = nlohmann::json::array();
  for (const Vec3& p : ov.trajectory) traj.push_back(xyz(p));
  j["rooms"] = std::move(rooms);
  j["walls"] = std::move(walls);
  j["goals"] = std::move(goals);
  j["trajectory"] = std::move(traj);
  j["episode"] = ov.episode;
  return j;
}

std::string sceneGraphHtml(const SceneGraph& g, const ViewerOverlay& overlay) {
  const std::string safe = jsonForScript(viewerData(g, overlay));
  std::string page(kPage);
  const size_t at = page.find(kDataMark);
  if (at == std::string::npos) throw std::logic_error("viewer page has no data mark");
  page.replace(at, std::string(kDataMark).size(), safe);
  return page;
}

void writeSceneGraphHtml(const std::filesystem::path& path, const SceneGraph& g, const ViewerOverlay& overlay) {
  writeFileAtomic(path, sceneGraphHtml(g, overlay));
}

}  // namespace ussnav
