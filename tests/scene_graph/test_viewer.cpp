// The scene graph as a web page (scene_graph/viewer.hpp, `ussnav graph view`, DIR/scene_graph.html
// from `explore`): the embedded data is the graph's (footprints, edges, coverage columns), no
// label can end the script block, and -- where node is installed -- the page's own script run on
// an explored two-room world picks, finds and describes what the scene graph holds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "support/test_worlds.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/scene_graph/viewer.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {
namespace {

namespace fs = std::filesystem;

// The JSON between the page's data tags.
nlohmann::json embedded(const std::string& page) {
  const std::string open = "<script id=\"ussnav-data\" type=\"application/json\">";
  const size_t a = page.find(open);
  const size_t b = page.find("</script>", a);
  EXPECT_NE(a, std::string::npos);
  return nlohmann::json::parse(page.substr(a + open.size(), b - a - open.size()));
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

nlohmann::json runPageScript(const fs::path& page);

TEST(Viewer, PageEmbedsTheGraphAndNoLabelEndsTheScript) {
  SceneGraph g;
  g.source = "hand";
  g.time = 3.5;
  g.nodes.push_back({0, Vec3(1, 2, 1.2), 1.5, {Vec3(0, 1, 0.5), Vec3(2, 1, 0.5), Vec3(1, 3, 2.0), Vec3(1, 2, 0.4)}, 0.0});
  g.nodes.push_back({4, Vec3(3.104, 2, 1.2), 1.25, {Vec3(2, 1, 0.5), Vec3(4, 1, 0.5), Vec3(4, 3, 0.5), Vec3(2, 3, 2.5)}, 0.3});
  g.edges.push_back({0, 4, "overlap", 1.0});
  g.edges.push_back({4, 0, "loop", 0.05, true});
  g.regions.push_back({7, {0, 4}, "bed</script><b>room", "", Vec3(2, 2, 1.2), {}});
  g.objects.push_back({1, "bed\xff", Vec3(3, 2, 0.3), Vec3(2, 1, 0), Vec3(4, 3, 0.6), 2, 4, 7});
  g.coverage = {1.0, 1.0, 3, 2.0, {Vec3i(0, 0, 0), Vec3i(1, 0, 0), Vec3i(0, 0, 1)}};
  ViewerOverlay ov;
  ov.trajectory = {Vec3(0.5, 0.5, 1.2), Vec3(3.0, 2.0, 1.2)};
  const std::string page = sceneGraphHtml(g, ov);
  EXPECT_EQ(count(page, "</script>"), 2u);  // the data block's and the script's own
  EXPECT_EQ(count(page, "__USSNAV_VIEWER_DATA__"), 0u);
  const nlohmann::json d = embedded(page);
  EXPECT_EQ(d["format"], "ussnav-viewer");
  EXPECT_EQ(d["title"], "hand");
  EXPECT_EQ(d["regions"][0]["label"], "bed</script><b>room");  // escaped in the page, the same once parsed
  EXPECT_EQ(d["objects"][0]["label"], "bed\xef\xbf\xbd");         // invalid UTF-8 replaced, not thrown
  EXPECT_EQ(d["objects"][0]["region"], 7);
  // Footprints: the x-y convex outline of each hull, interior points dropped, 1 cm rounding.
  ASSERT_EQ(d["nodes"].size(), 2u);
  std::set<std::pair<double, double>> f0;
  const auto& p0 = d["nodes"][0]["poly"];
  for (size_t i = 0; i + 1 < p0.size(); i += 2) f0.insert({p0[i].get<double>(), p0[i + 1].get<double>()});
  EXPECT_EQ(f0, (std::set<std::pair<double, double>>{{0, 1}, {2, 1}, {1, 3}}));
  EXPECT_EQ(d["nodes"][1]["poly"].size(), 8u);
  EXPECT_DOUBLE_EQ(d["nodes"][1]["c"][0].get<double>(), 3.1);
  EXPECT_EQ(d["nodes"][1]["region"], 7);
  // Edges as [a, b, type index, blocked]; type indices name the edge_types list.
  EXPECT_EQ(d["edges"][1], nlohmann::json({4, 0, 3, 1}));
  EXPECT_EQ(d["edge_types"][3]["name"], "loop");
  // Coverage: one column per visited x-y cell, whatever its height.
  EXPECT_EQ(d["coverage"]["columns"], nlohmann::json({{0, 0}, {1, 0}}));
  EXPECT_EQ(d["trajectory"].size(), 2u);
  EXPECT_TRUE(d["episode"].is_null());
  EXPECT_TRUE(d["rooms"].empty());

  // An episode's coarse decisions, listed and clickable (the page's script, under node).
  ov.episode = {{"goal", "bed"}, {"success", true}, {"spl", 0.5}, {"end_reason", "found"},
                {"choices", {{{"t", 1.5}, {"at", {0.5, 0.5}}, {"region", 7}, {"chance", 0.42}, {"global_utility", false},
                              {"fault", ""}, {"reason", "why 7"}},
                             {{"t", 9.0}, {"at", {3.0, 2.0}}, {"region", -1}, {"chance", 0.0}, {"global_utility", false},
                              {"fault", "malformed"}, {"reason", ""}}}}};
  const fs::path file = test::tempDir("viewer_hand") / "hand.html";
  writeSceneGraphHtml(file, g, ov);
  const nlohmann::json r = runPageScript(file);
  if (r.is_null()) GTEST_SKIP() << "node is not installed: the page's script was not run";
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["ui"]["choices"], 2);
  EXPECT_EQ(r["ui"]["choiceLines"][0], "t 1.5 s: region 7 (bed</script><b>room), chance 0.42");
  EXPECT_EQ(r["ui"]["choiceLines"][1], "t 9.0 s: global utility (malformed)");
  EXPECT_EQ(r["ui"]["choiceInfo"][0].get<std::string>().rfind("region 7 (bed</script><b>room): 2 nodes", 0), 0u)
      << r["ui"]["choiceInfo"];
  EXPECT_EQ(r["ui"]["choiceInfo"].back(), "why 7");
}

// The JSON report of tests/scene_graph/viewer_check.js on `page`, or null without node.
nlohmann::json runPageScript(const fs::path& page) {
  std::string out;
  if (test::runCommand("command -v node", &out) != 0) return nullptr;
  const std::string check = std::string(USSNAV_SOURCE_DIR) + "/tests/scene_graph/viewer_check.js";
  const int rc = test::runCommand("node " + check + " " + page.string() + " 2>&1", &out);
  EXPECT_EQ(rc, 0) << out;
  return rc == 0 ? nlohmann::json::parse(out) : nlohmann::json();
}

bool boxHolds(const nlohmann::json& o, double x, double y) {
  return x >= o["min"][0].get<double>() - 0.051 && x <= o["max"][0].get<double>() + 0.051 &&
         y >= o["min"][1].get<double>() - 0.051 && y <= o["max"][1].get<double>() + 0.051;
}

TEST(Viewer, ExploreWritesAPageWhoseScriptFindsWhatTheGraphHolds) {
  const fs::path dir = test::tempDir("viewer");
  World w = test::twoRooms(true);
  test::addObject(w, "bed", Vec3(8.5, 3.0, 0.3), Vec3(0.9, 0.7, 0.3));
  test::addObject(w, "chair", Vec3(1.5, 1.0, 0.45), Vec3(0.3, 0.3, 0.45));
  saveWorld(w, dir / "w.json");
  const std::string base = test::cliPath() + " --quiet ";
  std::string out;
  ASSERT_EQ(test::runCommand(base + "explore --world " + (dir / "w.json").string() +
                                 " --goal bed --planner full --max-time 120 --out " + (dir / "ep").string(),
                             &out),
            0)
      << out;
  const fs::path page = dir / "ep" / "scene_graph.html";
  ASSERT_TRUE(fs::exists(page));
  const SceneGraph g = loadSceneGraph(dir / "ep" / "scene_graph.json");
  const auto result = nlohmann::json::parse(std::ifstream(dir / "ep" / "result.json"));
  ASSERT_FALSE(g.objects.empty());

  // The CLI's own page, with the world and the flown trajectory added.
  ASSERT_EQ(test::runCommand(base + "graph view " + (dir / "ep" / "scene_graph.json").string() + " --world " +
                                 (dir / "w.json").string() + " --trajectory " + (dir / "ep" / "trajectory.csv").string() +
                                 " --title 'two rooms' --out " + (dir / "view.html").string(),
                             &out),
            0)
      << out;
  // Bad input: a trajectory row that is not numbers names the file and the line; nothing written.
  { std::ofstream(dir / "bad.csv") << "t,x,y,z,yaw\n0,1,2,1.2,0\n0.1,1,oops,1.2,0\n"; }
  EXPECT_EQ(test::runCommand(base + "graph view " + (dir / "ep" / "scene_graph.json").string() + " --trajectory " +
                                 (dir / "bad.csv").string() + " --out " + (dir / "bad.html").string(),
                             &out),
            2);
  EXPECT_NE(out.find("bad.csv"), std::string::npos) << out;
  EXPECT_NE(out.find("line 3"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "bad.html"));
  // A missing input is bad input too: exit 2 (not CLI11's own 105), the option named.
  EXPECT_EQ(test::runCommand(base + "graph view " + (dir / "missing.json").string() + " --out " + (dir / "m.html").string(), &out), 2);
  EXPECT_NE(out.find("missing.json"), std::string::npos) << out;
  EXPECT_EQ(test::runCommand(base + "graph view --help", &out), 0);

  const nlohmann::json r = runPageScript(page);
  if (r.is_null()) GTEST_SKIP() << "node is not installed: the page's script was not run";
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r["scripts"], 2);
  EXPECT_EQ(r["counts"]["nodes"], g.nodes.size());
  EXPECT_EQ(r["counts"]["edges"], g.edges.size());
  EXPECT_EQ(r["counts"]["regions"], g.regions.size());
  EXPECT_EQ(r["counts"]["objects"], g.objects.size());
  EXPECT_EQ(r["counts"]["rooms"], w.rooms.size());
  EXPECT_EQ(r["counts"]["goals"], 1);  // the bed
  EXPECT_GT(r["counts"]["trajectory"].get<int>(), 10);
  EXPECT_EQ(r["episode"]["goal"], "bed");
  EXPECT_EQ(r["episode"]["success"], result["success"]);
  // Every node centre lies in the page's bounds and picks a node (or an object over it).
  const auto& b = r["bounds"];
  for (const SgNode& n : g.nodes) {
    EXPECT_GE(n.centroid.x(), b[0].get<double>() - 0.01);
    EXPECT_LE(n.centroid.y(), b[3].get<double>() + 0.01);
  }
  std::map<int, nlohmann::json> objects;
  const nlohmann::json d = embedded([&] {
    std::ifstream in(page);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }());
  for (const auto& o : d["objects"]) objects[o["id"].get<int>()] = o;
  for (const auto& p : r["nodePicks"]) {
    ASSERT_NE(p[1], "none") << "node " << p[0];
    if (p[1] == "object") {
      EXPECT_TRUE(objects.count(p[2].get<int>()));
    }
  }
  EXPECT_EQ(r["farPick"], "none");
  for (const auto& k : r["bandPicks"]) EXPECT_NE(k, "node");  // no node centre in the band
  // The page's band starts around every node centre; a band above them all draws no polyhedron.
  double zlo = 1e9, zhi = -1e9;
  for (const SgNode& n : g.nodes) zlo = std::min(zlo, n.centroid.z()), zhi = std::max(zhi, n.centroid.z());
  EXPECT_LE(r["ui"]["band"][0].get<double>(), zlo);
  EXPECT_GE(r["ui"]["band"][1].get<double>(), zhi);
  EXPECT_GE(r["ui"]["fillsWithoutBand"].get<int>(), r["ui"]["fillsWithBand"].get<int>() + int(g.nodes.size()));
  // A click at an object's centre picks an object whose box holds that point (the smallest).
  for (const auto& p : r["objectPicks"]) {
    ASSERT_EQ(p[1], "object") << "object " << p[0];
    const auto& o = objects.at(p[0].get<int>());
    EXPECT_TRUE(boxHolds(objects.at(p[2].get<int>()), o["c"][0].get<double>(), o["c"][1].get<double>()));
  }
  // Search: case and spaces ignored; the beds of the graph, no more.
  std::vector<int> beds;
  for (const SgObject& o : g.objects)
    if (o.label.find("bed") != std::string::npos) beds.push_back(o.id);
  EXPECT_FALSE(beds.empty());
  EXPECT_EQ(r["search"]["bed"], nlohmann::json(beds));
  EXPECT_EQ(r["search"]["BED "], nlohmann::json(beds));
  EXPECT_TRUE(r["search"][""].empty());
  // Region details name the region's objects.
  for (size_t i = 0; i < g.regions.size(); ++i) {
    const std::string lines = r["regionLines"][i].dump();
    for (const SgObject& o : g.objects)
      if (o.region_id == g.regions[i].id) {
        EXPECT_NE(lines.find(o.label), std::string::npos) << lines;
      }
  }
  // The UI ran against the fake DOM: it drew, listed the regions, found the bed, and a click
  // at the first object's centre showed that object (or a smaller one over it).
  const auto& ui = r["ui"];
  EXPECT_EQ(ui["summary"].get<std::string>().rfind(std::to_string(g.nodes.size()) + " nodes", 0), 0u) << ui["summary"];
  EXPECT_EQ(ui["regionItems"], g.regions.size());
  EXPECT_GT(ui["strokesAtStart"].get<int>(), int(g.nodes.size()));
  EXPECT_GT(ui["strokesAfter"].get<int>(), ui["strokesAtStart"].get<int>());
  EXPECT_EQ(ui["matchesText"], std::to_string(beds.size()) + " found");
  ASSERT_FALSE(ui["clickedInfo"].empty());
  EXPECT_EQ(ui["clickedInfo"][0].get<std::string>().rfind("object ", 0), 0u) << ui["clickedInfo"];
  const std::string picked = objects.at(r["objectPicks"][0][2].get<int>())["label"];
  EXPECT_NE(ui["clickedInfo"][0].get<std::string>().find(picked), std::string::npos) << ui["clickedInfo"];

  // The coarse level's choices: result.json has them, the page lists them, a click on the first
  // describes the region it chose.
  const auto& choices = result["reasoning"]["choices"];
  ASSERT_TRUE(choices.is_array());
  EXPECT_EQ(ui["choices"], choices.size());
  EXPECT_EQ(r["episode"]["choices"], choices);
  const int first = choices.empty() ? -1 : choices[0]["region"].get<int>();
  if (first >= 0) {
    EXPECT_NE(ui["choiceLines"][0].get<std::string>().find("region " + std::to_string(first)), std::string::npos)
        << ui["choiceLines"][0];
    EXPECT_EQ(ui["choiceInfo"][0].get<std::string>().rfind("region " + std::to_string(first), 0), 0u) << ui["choiceInfo"];
  }
  for (size_t i = 1; i < choices.size(); ++i)  // logged as they change
    EXPECT_TRUE(choices[i]["region"] != choices[i - 1]["region"] || choices[i]["fault"] != choices[i - 1]["fault"]);

  const nlohmann::json v = runPageScript(dir / "view.html");
  ASSERT_TRUE(v.is_object());
  EXPECT_EQ(v["title"], "two rooms");
  EXPECT_EQ(v["counts"]["rooms"], w.rooms.size());
  EXPECT_GT(v["counts"]["walls"].get<int>(), 4);
  EXPECT_EQ(v["counts"]["trajectory"], r["counts"]["trajectory"]);
  EXPECT_TRUE(v["episode"].is_null());
}

}  // namespace
}  // namespace ussnav
