#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/world_io.hpp"
#include "ussnav/sim/world_stats.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

namespace {

fs::path dir() {
  static const auto d = test::tempDir("world_cli");
  return d;
}

int run(const std::string& args, std::string* out = nullptr) {
  return test::runCommand(test::cliPath() + " --quiet " + args, out);
}

std::string q(const fs::path& p) {
  std::string s = "'";
  s += p.string();
  s += "'";
  return s;
}

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(WorldCli, GenerateIsDeterministicAndRendersAndStats) {
  const auto a = dir() / "a.json", b = dir() / "b.json", png = dir() / "a.png";
  std::string out;
  ASSERT_EQ(run("world generate --style apartment --seed 2 --rooms 14 --out " + q(a), &out), 0) << out;
  EXPECT_NE(out.find("14 rooms"), std::string::npos) << out;
  ASSERT_EQ(run("world generate --style apartment --seed 2 --rooms 14 --out " + q(b)), 0);
  EXPECT_EQ(readFile(a), readFile(b));

  ASSERT_EQ(run("world render " + q(a) + " --out " + q(png), &out), 0) << out;
  const std::string bytes = readFile(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");

  // stats --json: exactly one JSON object on stdout, agreeing with the library.
  ASSERT_EQ(run("world stats --json " + q(a), &out), 0) << out;
  EXPECT_EQ(lines(out), 1) << out;
  const auto j = nlohmann::json::parse(out);
  const WorldStats s = computeWorldStats(loadWorld(a));
  EXPECT_EQ(j["rooms"], 14);
  EXPECT_EQ(j["objects"], s.objects);
  EXPECT_EQ(j["rooms_by_type"]["hallway"], s.rooms_by_type.at("hallway"));
  EXPECT_EQ(j["objects_by_category"].size(), s.objects_by_category.size());
  EXPECT_NEAR(j["floor_area_m2"].get<double>(), s.floor_area_m2, 1e-3);
  EXPECT_NEAR(j["free_volume_m3"].get<double>(), s.free_volume_m3, 1e-3);
  ASSERT_EQ(run("world stats " + q(a), &out), 0) << out;
  EXPECT_NE(out.find("rooms by type:"), std::string::npos) << out;
}

TEST(WorldCli, RendersAnObstacleOnlyWorld) {
  World w;
  w.obstacles.resolution = 0.2;
  for (int i = 0; i < 20; ++i) w.obstacles.cells.emplace_back(i, 0, i % 5);
  const auto p = dir() / "scan.json", png = dir() / "scan.png";
  saveWorld(w, p);
  std::string out;
  ASSERT_EQ(run("world render " + q(p) + " --out " + q(png), &out), 0) << out;
  EXPECT_TRUE(fs::exists(png));
  ASSERT_EQ(run("world stats --json " + q(p), &out), 0) << out;
  EXPECT_EQ(nlohmann::json::parse(out)["obstacle_voxels"], 20);
}

TEST(WorldCli, BadInputExitsTwoWithOneLineAndNoOutput) {
  const auto bad = dir() / "bad.json", png = dir() / "bad.png";
  std::ofstream(bad) << "{\"format\": \"ussnav-world\", \"version\": 1, \"rooms\": [";
  std::string out;
  EXPECT_EQ(run("world render " + q(bad) + " --out " + q(png), &out), 2) << out;
  EXPECT_EQ(lines(out), 1) << out;
  EXPECT_NE(out.find("bad.json"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(png));

  EXPECT_EQ(run("world stats --json " + q(bad), &out), 2) << out;
  EXPECT_EQ(lines(out), 1) << out;

  const auto gen = dir() / "castle.json";
  EXPECT_EQ(run("world generate --style castle --seed 1 --out " + q(gen), &out), 2) << out;
  EXPECT_EQ(lines(out), 1) << out;
  EXPECT_NE(out.find("style"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(gen));
  EXPECT_EQ(run("world generate --seed -3 --out " + q(gen), &out), 2) << out;
  EXPECT_NE(out.find("--seed"), std::string::npos) << out;
  EXPECT_EQ(run("world generate --rooms 99 --out " + q(gen), &out), 2) << out;
  EXPECT_NE(out.find("rooms"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(gen));

  // A semantically bad world (object outside every room) is refused by render, too.
  GeneratorParams gp;
  gp.seed = 9;
  gp.target_rooms = 8;
  auto j = worldToJson(generateWorld(gp));
  j["objects"][0]["center"] = {-100.0, -100.0, 0.5};
  const auto moved = dir() / "moved.json";
  std::ofstream(moved) << j.dump();
  EXPECT_EQ(run("world render " + q(moved) + " --out " + q(png), &out), 2) << out;
  EXPECT_NE(out.find("objects[0]"), std::string::npos) << out;
  EXPECT_EQ(lines(out), 1) << out;
  EXPECT_FALSE(fs::exists(png));
}

TEST(WorldCli, EverySubcommandHasHelp) {
  for (const char* sub : {"generate", "render", "stats", "categories"}) {
    std::string out;
    EXPECT_EQ(run(std::string("world ") + sub + " --help", &out), 0) << sub;
    EXPECT_NE(out.find("Usage"), std::string::npos) << sub << ": " << out;
  }
  std::string out;
  EXPECT_EQ(run("world --help", &out), 0);
  for (const char* sub : {"generate", "render", "stats"}) EXPECT_NE(out.find(sub), std::string::npos) << out;
}
