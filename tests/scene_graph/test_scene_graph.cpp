// SceneGraph document: JSON round trip, validation of corrupt documents (file + field in the
// error), and a Mapper run on a two-room world whose regions cover every node and whose scene
// graph survives save/load.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "support/test_worlds.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/perception/oracle_detector.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/sim/simulator.hpp"

namespace ussnav {
namespace {

namespace fs = std::filesystem;

SceneGraph handMade() {
  SceneGraph g;
  g.source = "hand";
  g.time = 12.25;
  g.nodes.push_back({0, Vec3(1, 2, 1.2), 1.5, {Vec3(0, 1, 0.5), Vec3(2, 1, 0.5), Vec3(1, 3, 2.0)}, 0.1});
  g.nodes.push_back({1, Vec3(3.1, 2, 1.2), 1.25, {Vec3(2, 1, 0.5), Vec3(4, 1, 0.5)}, 0.3});
  g.nodes.push_back({2, Vec3(0.1 + 0.2, -1e-7, 1.0 / 3.0), 0.9, {}, 1.0 / 7.0});  // awkward doubles
  g.edges.push_back({0, 1, "overlap", 1.0});
  g.edges.push_back({1, 2, "loop", 0.05});
  g.regions.push_back({0, {0, 1}, "", "", Vec3(2.05, 2, 1.2), {3}});
  g.regions.push_back({3, {2}, "kitchen", "a small kitchen", Vec3(0.3, 0, 0.3), {0}});
  g.objects.push_back({1, "chair", Vec3(1, 2, 0.4), Vec3(0.7, 1.7, 0), Vec3(1.3, 2.3, 0.9), 4, 0, 0});
  g.objects.push_back({5, "bed", Vec3(3, 2, 0.3), Vec3(2, 1, 0), Vec3(4, 3, 0.6), 2, -1, -1});
  g.coverage = {1.0, 1.0, 2, 1.5, {Vec3i(0, 0, 0), Vec3i(1, 0, 0)}};
  return g;
}

// One scratch folder per process, removed at exit.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() / ("ussnav_sg_" + std::to_string(::getpid()));
  ScratchDir() { fs::create_directories(path); }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

fs::path tmpFile(const std::string& name) {
  static ScratchDir dir;
  return dir.path / name;
}

// Writes `j` (or raw text) and expects loadSceneGraph to throw naming the file and `field`.
void expectRejected(const std::string& text, const std::string& field, const std::string& name) {
  const fs::path p = tmpFile(name);
  { std::ofstream(p) << text; }
  try {
    loadSceneGraph(p);
    FAIL() << "accepted corrupt document " << name;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), p.string());
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
}

TEST(SceneGraphIo, RoundTripIsExact) {
  const SceneGraph g = handMade();
  const fs::path p = tmpFile("round.json");
  saveSceneGraph(p, g);
  const SceneGraph back = loadSceneGraph(p);
  EXPECT_EQ(back, g);
  EXPECT_EQ(back.nodes[2].centroid.x(), 0.1 + 0.2);  // bit-exact, not merely close
  const nlohmann::json j = readJsonFile(p);
  EXPECT_EQ(j["format"], "ussnav-scene-graph");
  EXPECT_EQ(j["schema_version"], 1);
  SceneGraph changed = g;
  changed.objects[0].n_observations = 5;
  EXPECT_FALSE(changed == g);
  // A blocked edge survives the round trip; documents without the (optional) key load unblocked.
  SceneGraph blocked = g;
  blocked.edges[0].blocked = true;
  saveSceneGraph(p, blocked);
  EXPECT_EQ(loadSceneGraph(p), blocked);
  nlohmann::json old = toJson(blocked);
  for (auto& e : old["edges"]) e.erase("blocked");
  { std::ofstream(p) << old.dump(); }
  EXPECT_EQ(loadSceneGraph(p), g);
}

TEST(SceneGraphIo, CorruptDocumentsNameFileAndField) {
  const std::string good = toJson(handMade()).dump();
  expectRejected(good.substr(0, good.size() / 2), "", "truncated.json");

  nlohmann::json j = toJson(handMade());
  j.erase("nodes");
  expectRejected(j.dump(), "nodes", "no_nodes.json");

  j = toJson(handMade());
  j["edges"][1]["b"] = 17;
  expectRejected(j.dump(), "edges[1].b", "edge_unknown_node.json");

  j = toJson(handMade());
  j["nodes"][0]["radius"] = "wide";
  expectRejected(j.dump(), "nodes[0].radius", "wrong_type.json");

  j = toJson(handMade());
  j["nodes"][1]["id"] = 0;
  expectRejected(j.dump(), "nodes[1].id", "duplicate_node.json");

  j = toJson(handMade());
  j["objects"][0]["region_id"] = 9;
  expectRejected(j.dump(), "objects[0].region_id", "object_unknown_region.json");

  j = toJson(handMade());
  j["objects"][1]["node_id"] = 42;
  expectRejected(j.dump(), "objects[1].node_id", "object_unknown_node.json");

  j = toJson(handMade());
  j["edges"][0]["blocked"] = "maybe";
  expectRejected(j.dump(), "edges[0].blocked", "edge_blocked.json");

  j = toJson(handMade());
  j["edges"][0]["type"] = "teleport";
  expectRejected(j.dump(), "edges[0].type", "edge_type.json");

  j = toJson(handMade());
  j["regions"][0]["centroid"] = {1, 2};
  expectRejected(j.dump(), "regions[0].centroid", "short_vector.json");

  j = toJson(handMade());
  j["coverage"].erase("visited");
  expectRejected(j.dump(), "coverage.visited", "no_visited.json");
}

TEST(SceneGraphIo, CountsPerLayer) {
  const SceneGraphCounts c = countLayers(handMade());
  EXPECT_EQ(c.nodes, 3);
  EXPECT_EQ(c.edges, 2);
  EXPECT_EQ(c.regions, 2);
  EXPECT_EQ(c.labelled_regions, 1);
  ASSERT_EQ(c.edges_by_type.size(), 4u);
  EXPECT_EQ(c.edges_by_type[1], (std::pair<std::string, int>("overlap", 1)));
  EXPECT_EQ(c.edges_by_type[3], (std::pair<std::string, int>("loop", 1)));
  EXPECT_EQ(c.edges_by_type[0].second, 0);
  ASSERT_EQ(c.objects_by_label.size(), 2u);
}

// Flies through the door of twoRooms and back: the regions must partition every node, objects
// must carry the region of their anchor node, and the snapshot must survive save/load.
TEST(SceneGraphPipeline, MapperRegionsCoverAllNodesAndRoundTrip) {
  World w = test::twoRooms(true);
  test::addObject(w, "bed", Vec3(1.5, 3.0, 0.3), Vec3(0.9, 0.7, 0.3));
  test::addObject(w, "chair", Vec3(8.5, 1.0, 0.45), Vec3(0.3, 0.3, 0.45));
  Config cfg;
  Simulator sim(w, cfg, 3);
  MapperOptions opt;
  auto det = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), 3);
  Mapper mapper(cfg, opt, std::move(det));
  const double z = 1.2;
  double t = 0.0;
  int region_updates = 0;
  auto fly = [&](const Vec3& from, const Vec3& to, double yaw, int steps) {
    for (int i = 0; i < steps; ++i) {
      const Pose pose{from + (to - from) * (double(i) / steps), yaw};
      SensedFrame f = sim.sense(pose, t);
      const MapperFrameReport rep = mapper.process({f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
      region_updates += rep.regions_updated ? 1 : 0;
      t += 0.2;
    }
  };
  fly(Vec3(1.0, 2.0, z), Vec3(9.0, 2.0, z), 0.0, 24);
  fly(Vec3(9.0, 2.0, z), Vec3(1.0, 2.0, z), M_PI, 12);

  const ConnectivityGraph& g = mapper.graph();
  ASSERT_GT(g.size(), 4u);
  EXPECT_GT(region_updates, 0);
  EXPECT_LT(region_updates, 36);  // frames with nothing new skip the region stage
  ASSERT_GT(mapper.times().samples().count("regions"), 0u);
  size_t covered = 0;
  for (const auto& [id, r] : mapper.regions().regions()) covered += r.nodes.size();
  EXPECT_EQ(covered, g.size());
  for (const ScgNode& n : g.nodes()) EXPECT_GE(mapper.regions().regionOf(n.id), 0) << "node " << n.id;

  const SceneGraph sg = buildSceneGraph(mapper, t, "two rooms");
  EXPECT_EQ(sg.nodes.size(), g.size());
  EXPECT_EQ(sg.edges.size(), g.edges().size());
  EXPECT_EQ(sg.regions.size(), mapper.regions().regions().size());
  EXPECT_GT(sg.coverage.visited_cells, 0);
  EXPECT_EQ(size_t(sg.coverage.visited_cells), sg.coverage.visited.size());
  for (const SgNode& n : sg.nodes) EXPECT_GE(n.hull.size(), 4u);
  ASSERT_FALSE(sg.objects.empty());
  for (const SgObject& o : sg.objects) {
    ASSERT_GE(o.node_id, 0);
    EXPECT_EQ(o.region_id, mapper.regions().regionOf(o.node_id)) << o.label;
  }
  const fs::path p = tmpFile("mapper.json");
  saveSceneGraph(p, sg);
  EXPECT_EQ(loadSceneGraph(p), sg);
}


// An object seen through a door belongs to a node on its own side of the wall (one that sees it),
// not to the node the UAV looked from; an object in the UAV's room stays in that room.
TEST(SceneGraphPipeline, ObjectsSeenThroughADoorAnchorBeyondIt) {
  World w = test::twoRooms(true);
  const int chair_b = test::addObject(w, "chair", Vec3(7.0, 2.0, 0.45), Vec3(0.3, 0.3, 0.45));
  const int table_a = test::addObject(w, "table", Vec3(2.0, 3.3, 0.4), Vec3(0.5, 0.4, 0.4));
  Config cfg;
  Simulator sim(w, cfg, 3);
  auto det = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), 3);
  Mapper mapper(cfg, MapperOptions{}, std::move(det));
  double t = 0.0;
  for (int i = 0; i < 40; ++i) {  // forward in room A (x < 5) up to the door, looking through it
    const Pose pose{Vec3(1.0 + 3.6 * std::min(i, 30) / 30.0, 2.0, 1.2), 0.0};
    SensedFrame f = sim.sense(pose, t);
    mapper.process({f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
    t += 0.2;
  }
  const ConnectivityGraph& g = mapper.graph();
  ASSERT_TRUE(mapper.objects());
  bool saw_chair = false, saw_table = false;
  for (const MappedObject& o : mapper.objects()->objects()) {
    ASSERT_GE(o.node_id, 0) << o.label;
    const Vec3& n = g.node(o.node_id).center;
    EXPECT_EQ(o.region_id, mapper.regions().regionOf(o.node_id));
    if (o.label == "chair" && (o.centroid - w.objects[size_t(chair_b - 1)].box.center).norm() < 0.6) {
      saw_chair = true;
      EXPECT_GT(n.x(), 5.05) << "chair anchored to node " << o.node_id << " at " << n.transpose();
    }
    if (o.label == "table" && (o.centroid - w.objects[size_t(table_a - 1)].box.center).norm() < 0.8) {
      saw_table = true;
      EXPECT_LT(n.x(), 4.95) << "table anchored to node " << o.node_id << " at " << n.transpose();
    }
  }
  EXPECT_TRUE(saw_chair);
  EXPECT_TRUE(saw_table);
}

}  // namespace
}  // namespace ussnav
