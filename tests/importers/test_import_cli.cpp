#include <gtest/gtest.h>

#include <fstream>

#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

TEST(ImportDispatch, PicksTheLoaderFromPathAndContent) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const fs::path d = test::sharedData();
  EXPECT_EQ(detectImportFormat(d / "procthor_houses/houses/house_3.json"), ImportFormat::kProcthor);
  EXPECT_EQ(detectImportFormat(d / "webots_complete_apartment"), ImportFormat::kWebots);
  EXPECT_EQ(detectImportFormat(d / "webots_complete_apartment/complete_apartment.wbt"), ImportFormat::kWebots);
  EXPECT_EQ(detectImportFormat(d / "freiburg_octomaps/geb079.bt"), ImportFormat::kScan);
  EXPECT_EQ(detectImportFormat(d / "freiburg_octomaps/geb079_occupied.pcd"), ImportFormat::kScan);
}

TEST(ImportDispatch, UnknownInputsNameTheFileAndTheAcceptedFormats) {
  const auto dir = test::tempDir("dispatch");
  const auto xyz = dir / "points.xyz";
  std::ofstream(xyz) << "1 2 3\n";
  try {
    importWorld(xyz);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("points.xyz"), std::string::npos) << m;
    EXPECT_NE(m.find("ProcTHOR"), std::string::npos) << m;
    EXPECT_NE(m.find(".pcd"), std::string::npos) << m;
  }
  const auto other = dir / "other.json";
  std::ofstream(other) << R"({"rooms": [{"name": "a"}]})";
  EXPECT_THROW(importWorld(other), InputError);
  EXPECT_THROW(importWorld(dir / "does_not_exist.bt"), InputError);
  EXPECT_THROW(importWorld(dir), InputError);  // a folder without rooms_enu.tsv
}

TEST(ImportCli, WritesAWorldAndPrintsASummary) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const auto out = test::tempDir("import_cli") / "house.json";
  std::string text;
  const std::string house = (test::sharedData() / "procthor_houses/houses/house_2.json").string();
  const int rc = test::runCommand(test::cliPath() + " world import " + house + " --out " + out.string(), &text);
  ASSERT_EQ(rc, 0) << text;
  EXPECT_NE(text.find("4 rooms"), std::string::npos) << text;
  EXPECT_NE(text.find("0 dropped"), std::string::npos) << text;
  const World w = loadWorld(out);
  EXPECT_EQ(w.rooms.size(), 4u);
  EXPECT_EQ(w.source, "procthor:house_2.json");
}

TEST(ImportCli, BadInputExitsTwoAndWritesNothing) {
  const auto dir = test::tempDir("import_cli_bad");
  const auto bad = dir / "broken.json";
  std::ofstream(bad) << R"({"rooms": [{"floorPolygon": )";
  const auto out = dir / "never.json";
  std::string text;
  const int rc = test::runCommand(test::cliPath() + " world import " + bad.string() + " --out " + out.string(), &text);
  EXPECT_EQ(rc, 2) << text;
  EXPECT_NE(text.find("broken.json"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(out));
}
