// `ussnav map` end to end on a two-room world: stats.json keeps the names issue 4 fixed (frames,
// grid, coverage, stage_ms with median / p95), the scene graph it writes loads, its web page
// holds the world's rooms and the flight, and a trajectory CSV with a header (explore's
// t,x,y,z,yaw) is read by column name.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "support/test_worlds.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {
namespace {

namespace fs = std::filesystem;

nlohmann::json pageData(const fs::path& page) {
  std::ifstream in(page);
  const std::string html(std::istreambuf_iterator<char>(in), {});
  const std::string open = "<script id=\"ussnav-data\" type=\"application/json\">";
  const size_t a = html.find(open), b = html.find("</script>", a);
  if (a == std::string::npos || b == std::string::npos) return nullptr;
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

TEST(MapCli, WritesStatsTheSceneGraphAndItsPage) {
  const fs::path dir = test::tempDir("map_cli");
  World w = test::twoRooms(true);
  test::addObject(w, "bed", Vec3(8.5, 3.0, 0.3), Vec3(0.9, 0.7, 0.3));
  saveWorld(w, dir / "w.json");
  const std::string base = test::cliPath() + " --quiet map --world " + (dir / "w.json").string();
  std::string out;
  ASSERT_EQ(test::runCommand(base + " --skeleton --max-frames 60 --out " + (dir / "lawn").string(), &out), 0) << out;
  const auto stats = nlohmann::json::parse(std::ifstream(dir / "lawn" / "stats.json"));
  EXPECT_EQ(stats["frames"], 60);
  EXPECT_GT(stats["grid"]["known_voxels"].get<int>(), 0);
  EXPECT_GT(stats["grid"]["bytes"].get<int>(), 0);
  EXPECT_GT(stats["coverage"]["visited_cells"].get<int>(), 0);
  EXPECT_GT(stats["coverage"]["explored_area_m2"].get<double>(), 0.0);
  for (const char* stage : {"grid", "coverage", "skeleton", "update"}) {
    ASSERT_TRUE(stats["stage_ms"].contains(stage)) << stage;
    EXPECT_LE(stats["stage_ms"][stage]["median"].get<double>(), stats["stage_ms"][stage]["p95"].get<double>()) << stage;
  }
  const SceneGraph g = loadSceneGraph(dir / "lawn" / "scene_graph.json");
  EXPECT_EQ(int(g.nodes.size()), stats["skeleton"]["nodes"].get<int>());
  EXPECT_GT(g.nodes.size(), 4u);
  const auto page = pageData(dir / "lawn" / "scene_graph.html");
  ASSERT_TRUE(page.is_object());
  EXPECT_EQ(page["nodes"].size(), g.nodes.size());
  EXPECT_EQ(page["rooms"].size(), 2u);
  EXPECT_EQ(page["trajectory"].size(), 60u);  // the pose of each frame sensed

  // explore's trajectory.csv columns: t first. Read as x,y,z the flight would stay near x = 0-1.
  { std::ofstream(dir / "t.csv") << "t,x,y,z,yaw\n0.0,1.5,2.0,1.2,0\n1.0,8.5,2.0,1.2,0\n"; }
  ASSERT_EQ(test::runCommand(base + " --trajectory " + (dir / "t.csv").string() + " --out " + (dir / "csv").string(), &out), 0)
      << out;
  const auto flown = pageData(dir / "csv" / "scene_graph.html");
  ASSERT_TRUE(flown.is_object());
  double max_x = 0.0;
  for (const auto& p : flown["trajectory"]) max_x = std::max(max_x, p[0].get<double>());
  EXPECT_GT(max_x, 7.5);
  // A bad row names the file and the line; nothing is written.
  { std::ofstream(dir / "bad.csv") << "x,y,z\n1,2,1.2\n3,two,1.2\n"; }
  EXPECT_EQ(test::runCommand(base + " --trajectory " + (dir / "bad.csv").string() + " --out " + (dir / "bad").string(), &out), 2);
  EXPECT_NE(out.find("bad.csv"), std::string::npos) << out;
  EXPECT_NE(out.find("line 3"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "bad" / "stats.json"));
}

}  // namespace
}  // namespace ussnav
