#include "ussnav/scene_graph/io.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {
namespace {

using nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

// Reads fields of one JSON object, naming "parent.key" in every error.
class Reader {
 public:
  Reader(const std::string& src, const json& j, std::string path) : src_(src), j_(j), path_(std::move(path)) {
    if (!j_.is_object()) fail(path_, "an object");
  }
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(src_, field, "expected " + what);
  }
  std::string name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const json& at(const std::string& key) const {
    auto it = j_.find(key);
    if (it == j_.end()) throw InputError(src_, name(key), "missing key");
    return *it;
  }
  double number(const std::string& key) const { return numberOf(at(key), name(key)); }
  int integer(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_number_integer()) fail(name(key), "an integer");
    return v.get<int>();
  }
  int64_t integer64(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_number_integer()) fail(name(key), "an integer");
    return v.get<int64_t>();
  }
  std::string string(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_string()) fail(name(key), "a string");
    return v.get<std::string>();
  }
  const json& array(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_array()) fail(name(key), "an array");
    return v;
  }
  Vec3 vec3(const std::string& key) const { return vec3Of(at(key), name(key)); }
  std::vector<int> ints(const std::string& key) const {
    std::vector<int> out;
    const json& a = array(key);
    for (size_t i = 0; i < a.size(); ++i) {
      if (!a[i].is_number_integer()) fail(name(key) + "[" + std::to_string(i) + "]", "an integer");
      out.push_back(a[i].get<int>());
    }
    return out;
  }
  double numberOf(const json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(field, "a finite number");
    return x;
  }
  Vec3 vec3Of(const json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 3) fail(field, "an array of 3 numbers");
    return {numberOf(v[0], field + "[0]"), numberOf(v[1], field + "[1]"), numberOf(v[2], field + "[2]")};
  }

 private:
  const std::string& src_;
  const json& j_;
  std::string path_;
};

std::string item(const std::string& list, size_t i) { return list + "[" + std::to_string(i) + "]"; }

void requireUnique(const std::string& src, std::set<int>& seen, int id, const std::string& field) {
  if (!seen.insert(id).second) throw InputError(src, field, "duplicate id " + std::to_string(id));
}

}  // namespace

json toJson(const SceneGraph& g) {
  json j;
  j["format"] = SceneGraph::kFormat;
  j["schema_version"] = g.schema_version;
  j["source"] = g.source;
  j["time"] = g.time;
  json nodes = json::array();
  for (const auto& n : g.nodes) {
    json hull = json::array();
    for (const auto& p : n.hull) hull.push_back(vec(p));
    nodes.push_back({{"id", n.id}, {"centroid", vec(n.centroid)}, {"radius", n.radius}, {"hull", hull},
                     {"created", n.created}});
  }
  j["nodes"] = nodes;
  json edges = json::array();
  for (const auto& e : g.edges)
    edges.push_back({{"a", e.a}, {"b", e.b}, {"type", e.type}, {"weight", e.weight}, {"blocked", e.blocked}});
  j["edges"] = edges;
  json regions = json::array();
  for (const auto& r : g.regions)
    regions.push_back({{"id", r.id}, {"nodes", r.nodes}, {"label", r.label}, {"description", r.description},
                       {"centroid", vec(r.centroid)}, {"adjacent", r.adjacent}});
  j["regions"] = regions;
  json objects = json::array();
  for (const auto& o : g.objects)
    objects.push_back({{"id", o.id}, {"label", o.label}, {"centroid", vec(o.centroid)},
                       {"bbox_min", vec(o.bbox_min)}, {"bbox_max", vec(o.bbox_max)},
                       {"n_observations", o.n_observations}, {"node_id", o.node_id}, {"region_id", o.region_id}});
  j["objects"] = objects;
  json cells = json::array();
  for (const auto& c : g.coverage.visited) cells.push_back({c.x(), c.y(), c.z()});
  j["coverage"] = {{"cell_size", g.coverage.cell_size},         {"cell_height", g.coverage.cell_height},
                   {"visited_cells", g.coverage.visited_cells}, {"explored_area_m2", g.coverage.explored_area_m2},
                   {"visited", cells}};
  return j;
}

SceneGraph sceneGraphFromJson(const json& j, const std::string& src) {
  SceneGraph g;
  const Reader top(src, j, "");
  if (top.string("format") != SceneGraph::kFormat)
    top.fail("format", std::string("\"") + SceneGraph::kFormat + "\"");
  g.schema_version = top.integer("schema_version");
  if (g.schema_version != SceneGraph::kSchemaVersion)
    top.fail("schema_version", std::to_string(SceneGraph::kSchemaVersion) + " (got " +
                                   std::to_string(g.schema_version) + ")");
  g.source = top.string("source");
  g.time = top.number("time");

  std::set<int> node_ids;
  const json& nodes = top.array("nodes");
  for (size_t i = 0; i < nodes.size(); ++i) {
    const Reader r(src, nodes[i], item("nodes", i));
    SgNode n;
    n.id = r.integer("id");
    requireUnique(src, node_ids, n.id, r.name("id"));
    n.centroid = r.vec3("centroid");
    n.radius = r.number("radius");
    const json& hull = r.array("hull");
    for (size_t k = 0; k < hull.size(); ++k) n.hull.push_back(r.vec3Of(hull[k], item(r.name("hull"), k)));
    n.created = r.number("created");
    g.nodes.push_back(std::move(n));
  }
  const json& edges = top.array("edges");
  for (size_t i = 0; i < edges.size(); ++i) {
    const Reader r(src, edges[i], item("edges", i));
    SgEdge e{r.integer("a"), r.integer("b"), r.string("type"), r.number("weight"), false};
    if (const auto it = edges[i].find("blocked"); it != edges[i].end()) {  // optional, default false
      if (!it->is_boolean()) r.fail(r.name("blocked"), "true or false");
      e.blocked = it->get<bool>();
    }
    for (const char* end : {"a", "b"}) {
      const int id = std::string(end) == "a" ? e.a : e.b;
      if (!node_ids.count(id)) throw InputError(src, r.name(end), "unknown node id " + std::to_string(id));
    }
    bool known = false;
    for (int t = 0; t < kEdgeTypeCount; ++t) known |= e.type == edgeTypeName(EdgeType(t));
    if (!known) r.fail(r.name("type"), "kinematic, overlap, visible or loop (got \"" + e.type + "\")");
    if (e.weight < 0) r.fail(r.name("weight"), "a weight >= 0");
    g.edges.push_back(std::move(e));
  }
  std::set<int> region_ids;
  std::set<int> nodes_in_regions;
  const json& regions = top.array("regions");
  for (size_t i = 0; i < regions.size(); ++i) {
    const Reader r(src, regions[i], item("regions", i));
    SgRegion reg;
    reg.id = r.integer("id");
    requireUnique(src, region_ids, reg.id, r.name("id"));
    reg.nodes = r.ints("nodes");
    for (size_t k = 0; k < reg.nodes.size(); ++k) {
      if (!node_ids.count(reg.nodes[k]))
        throw InputError(src, item(r.name("nodes"), k), "unknown node id " + std::to_string(reg.nodes[k]));
      if (!nodes_in_regions.insert(reg.nodes[k]).second)
        throw InputError(src, item(r.name("nodes"), k),
                         "node " + std::to_string(reg.nodes[k]) + " already belongs to another region");
    }
    reg.label = r.string("label");
    reg.description = r.string("description");
    reg.centroid = r.vec3("centroid");
    reg.adjacent = r.ints("adjacent");
    g.regions.push_back(std::move(reg));
  }
  for (size_t i = 0; i < g.regions.size(); ++i)
    for (size_t k = 0; k < g.regions[i].adjacent.size(); ++k)
      if (!region_ids.count(g.regions[i].adjacent[k]))
        throw InputError(src, item(item("regions", i) + ".adjacent", k),
                         "unknown region id " + std::to_string(g.regions[i].adjacent[k]));
  std::set<int> object_ids;
  const json& objects = top.array("objects");
  for (size_t i = 0; i < objects.size(); ++i) {
    const Reader r(src, objects[i], item("objects", i));
    SgObject o;
    o.id = r.integer("id");
    requireUnique(src, object_ids, o.id, r.name("id"));
    o.label = r.string("label");
    o.centroid = r.vec3("centroid");
    o.bbox_min = r.vec3("bbox_min");
    o.bbox_max = r.vec3("bbox_max");
    o.n_observations = r.integer("n_observations");
    o.node_id = r.integer("node_id");
    o.region_id = r.integer("region_id");
    if (o.node_id != -1 && !node_ids.count(o.node_id))
      throw InputError(src, r.name("node_id"), "unknown node id " + std::to_string(o.node_id) + " (or -1)");
    if (o.region_id != -1 && !region_ids.count(o.region_id))
      throw InputError(src, r.name("region_id"), "unknown region id " + std::to_string(o.region_id) + " (or -1)");
    g.objects.push_back(std::move(o));
  }
  const Reader c(src, top.at("coverage"), "coverage");
  g.coverage.cell_size = c.number("cell_size");
  g.coverage.cell_height = c.number("cell_height");
  g.coverage.visited_cells = c.integer64("visited_cells");
  g.coverage.explored_area_m2 = c.number("explored_area_m2");
  const json& cells = c.array("visited");
  for (size_t i = 0; i < cells.size(); ++i) {
    const json& v = cells[i];
    const std::string field = item("coverage.visited", i);
    if (!v.is_array() || v.size() != 3 || !v[0].is_number_integer() || !v[1].is_number_integer() ||
        !v[2].is_number_integer())
      c.fail(field, "an array of 3 integers");
    g.coverage.visited.emplace_back(v[0].get<int>(), v[1].get<int>(), v[2].get<int>());
  }
  // Lookups (nodeIndex, regionIndex) rely on ascending ids; files from elsewhere may not be.
  auto by_id = [](const auto& a, const auto& b) { return a.id < b.id; };
  std::sort(g.nodes.begin(), g.nodes.end(), by_id);
  std::sort(g.regions.begin(), g.regions.end(), by_id);
  std::sort(g.objects.begin(), g.objects.end(), by_id);
  return g;
}

void saveSceneGraph(const std::filesystem::path& path, const SceneGraph& g) { writeJsonAtomic(path, toJson(g)); }

SceneGraph loadSceneGraph(const std::filesystem::path& path) {
  return sceneGraphFromJson(readJsonFile(path), path.string());
}

}  // namespace ussnav
