// Suite files and the eval report: parsing with clear errors, CSV round trip (and recovery from
// a cut line), and summary numbers against hand computation.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/eval/eval_report.hpp"
#include "ussnav/eval/suite.hpp"

using namespace ussnav;

namespace {

std::filesystem::path writeText(const std::string& name, const std::string& text) {
  const auto dir = test::tempDir("eval_report");
  const auto p = dir / name;
  std::ofstream(p) << text;
  return p;
}

EpisodeRow row(const std::string& planner, const std::string& split, bool success, double spl, double len) {
  EpisodeRow r;
  r.world = "w", r.goal = "bed", r.planner = planner, r.split = split, r.success = success, r.spl = spl;
  r.path_length_m = len, r.shortest_path_m = 5.0, r.time_s = 2 * len, r.frames = 10, r.collisions = 0;
  r.end_reason = success ? "found" : "explored";
  return r;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Suite, ParsesWorldsGoalsSeedsAndResolvesPathsAgainstTheFile) {
  const auto p = writeText("suite.yaml",
                           "name: t\nmax_time_s: 50\nseeds: [1, 2]\ngoals: [bed, sofa]\nworlds:\n"
                           "  - generate: {style: apartment, seed: 4, rooms: 7}\n"
                           "  - file: worlds/a.json\n    goals: [toilet]\n    start: [1, 2, 1.2]\n");
  const Suite s = loadSuite(p);
  EXPECT_EQ(s.name, "t");
  ASSERT_EQ(s.worlds.size(), 2u);
  EXPECT_EQ(s.worlds[0].kind, SuiteWorld::Kind::Generate);
  EXPECT_EQ(s.worlds[0].generate.style, "apartment");
  EXPECT_EQ(s.worlds[0].generate.seed, 4u);
  EXPECT_EQ(s.worlds[0].generate.target_rooms, 7);
  EXPECT_EQ(s.worlds[0].name, "apartment-4-r7");
  EXPECT_EQ(s.worlds[1].path, p.parent_path() / "worlds/a.json");
  EXPECT_EQ(s.worlds[1].goals, std::vector<std::string>{"toilet"});
  ASSERT_TRUE(s.worlds[1].start.has_value());
  EXPECT_DOUBLE_EQ(s.worlds[1].start->position.y(), 2.0);
  EXPECT_EQ(s.seeds, (std::vector<uint64_t>{1, 2}));
  EXPECT_DOUBLE_EQ(*s.max_time_s, 50.0);
}

TEST(Suite, BadFilesNameTheField) {
  EXPECT_NE(errorOf([] { loadSuite(writeText("a.yaml", "worlds: []\ngoals: [bed]\n")); }).find("worlds"), std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite(writeText("b.yaml", "worlds:\n  - generate: {style: castle}\ngoals: [bed]\n")); })
                .find("worlds[0].generate.style"),
            std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite(writeText("c.yaml", "worlds:\n  - generate: {}\n    colour: red\ngoals: [bed]\n")); })
                .find("worlds[0].colour"),
            std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite(writeText("d.yaml", "worlds:\n  - generate: {}\n")); }).find("goals"), std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite(writeText("e.yaml", "worlds: [\n")); }).find("YAML"), std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite(writeText("f.yaml", "worlds:\n  - generate: {}\n  - generate: {}\ngoals: [bed]\n")); })
                .find("duplicate"),
            std::string::npos);
  EXPECT_NE(errorOf([] { loadSuite("/nonexistent/suite.yaml"); }).find("cannot read"), std::string::npos);
}

TEST(EvalReport, CsvRoundTripAndCutLinesAreSkipped) {
  EpisodeRow a = row("frontier", "multi_room", true, 0.4, 12.5);
  a.found_label = "bed, king size";  // commas cannot break the row
  const auto p = writeText("episodes.csv", csvHeader() + "\n" + toCsv(a) + "\n" + "w,bed,full,1,multi_ro\n");
  int bad = 0;
  const auto rows = readEpisodesCsv(p, &bad);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(bad, 1);
  EXPECT_EQ(rows[0].key(), a.key());
  EXPECT_NEAR(rows[0].spl, 0.4, 1e-4);
  EXPECT_NEAR(rows[0].path_length_m, 12.5, 1e-3);
  EXPECT_EQ(rows[0].found_label, "bed  king size");
}

TEST(EvalReport, SummaryMatchesHandComputation) {
  const std::vector<EpisodeRow> rows = {row("frontier", "single_room", true, 0.5, 10), row("frontier", "multi_room", false, 0, 30),
                                        row("frontier", "multi_room", true, 0.25, 20), row("full", "multi_room", true, 1.0, 5)};
  const auto j = summaryJson(rows);
  EXPECT_EQ(j["frontier"]["all"]["episodes"].get<int>(), 3);
  EXPECT_NEAR(j["frontier"]["all"]["sr"].get<double>(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(j["frontier"]["all"]["spl"].get<double>(), 0.75 / 3.0, 1e-12);
  EXPECT_NEAR(j["frontier"]["multi_room"]["sr"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(j["frontier"]["multi_room"]["spl"].get<double>(), 0.125, 1e-12);
  EXPECT_NEAR(j["frontier"]["multi_room"]["path_length_m"].get<double>(), 25.0, 1e-12);
  EXPECT_EQ(j["full"]["single_room"]["episodes"].get<int>(), 0);
  EXPECT_NEAR(j["full"]["multi_room"]["spl"].get<double>(), 1.0, 1e-12);
  const std::string md = summaryMarkdown(rows, "t");
  EXPECT_NE(md.find("| frontier | 3 | 0.667 | 0.250 |"), std::string::npos) << md;
}
