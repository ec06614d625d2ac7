// Suite files and the eval report: parsing with clear errors, CSV round trip (and recovery from
// a cut line), summary numbers against hand computation, and the suites shipped in configs/suites.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "support/input_error.hpp"
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
  r.end_reason = std::string(success ? "found" : "explored");
  return r;
}

using test::errorOf;

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
  EXPECT_NE(errorOf([] { loadSuite(writeText("g.yaml", "worlds:\n  - generate: {rooms: 40}\ngoals: [bed]\n")); })
                .find("worlds[0].generate.rooms"),
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
  // A number with something after it is not a number ("0.4000x" was read as 0.4); a line ending
  // in CR (the file saved on Windows) still reads.
  std::string trailing = toCsv(a);
  trailing.replace(trailing.find(",0.4000,"), 8, ",0.4000x,");
  EXPECT_TRUE(readEpisodesCsv(writeText("trailing.csv", csvHeader() + "\n" + trailing + "\n"), &bad).empty());
  EXPECT_EQ(bad, 1);
  const auto crlf = readEpisodesCsv(writeText("crlf.csv", csvHeader() + "\r\n" + toCsv(a) + "\r\n"), &bad);
  ASSERT_EQ(crlf.size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(crlf[0].key(), a.key());
}

TEST(EvalReport, RegionLabelColumnsRoundTripAndOldFilesStillLoad) {
  EpisodeRow a = row("full", "multi_room", true, 0.4, 12.5);
  a.labels_scored = 7, a.labels_correct = 3;
  const std::string old_header =
      "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
      "found_label,update_hz,wall_s";
  const std::string old_row = "w,tv,frontier,1,single_room,1,0.5000,4.000,2.000,8.00,80,0,found,tv,50.0,1.00";
  int bad = 0;
  const auto rows = readEpisodesCsv(writeText("labels.csv", csvHeader() + "\n" + toCsv(a) + "\n"), &bad);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(rows[0].labels_scored, 7);
  EXPECT_EQ(rows[0].labels_correct, 3);
  // A label column that is not a number: the row is dropped and counted, not read as 0.
  std::string garbled = toCsv(a);
  garbled.replace(garbled.rfind(",3"), 2, ",x");
  EXPECT_TRUE(readEpisodesCsv(writeText("garbled.csv", csvHeader() + "\n" + garbled + "\n"), &bad).empty());
  EXPECT_EQ(bad, 1);
  const auto old = readEpisodesCsv(writeText("old.csv", old_header + "\n" + old_row + "\n"), &bad);
  ASSERT_EQ(old.size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(old[0].labels_scored, 0);
  EXPECT_NEAR(old[0].spl, 0.5, 1e-9);

  EpisodeRow b = row("full", "single_room", true, 0.2, 9.0);
  b.labels_scored = 3, b.labels_correct = 3;
  const auto j = summaryJson({a, b, row("frontier", "multi_room", true, 0.3, 10)});
  EXPECT_EQ(j["full"]["region_labels"]["scored"].get<int>(), 10);
  EXPECT_EQ(j["full"]["region_labels"]["correct"].get<int>(), 6);
  EXPECT_NEAR(j["full"]["region_labels"]["accuracy"].get<double>(), 0.6, 1e-12);
  EXPECT_FALSE(j["frontier"].contains("region_labels"));
  const std::string md = summaryMarkdown({a, b}, "t");
  EXPECT_NE(md.find("| full | 10 | 6 | 0.600 |"), std::string::npos) << md;
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

TEST(EvalReport, LongHorizonSplitAndPairedTableMatchHandComputation) {
  // Two worlds x two seeds; L* of 20 m makes a multi-room row long-horizon, 5 m does not.
  auto at = [](EpisodeRow r, const std::string& world, uint64_t seed, double shortest) {
    r.world = world, r.seed = seed, r.shortest_path_m = shortest;
    return r;
  };
  const std::vector<EpisodeRow> rows = {
      at(row("frontier", "multi_room", true, 0.2, 40), "a", 1, 20), at(row("full", "multi_room", true, 0.5, 16), "a", 1, 20),
      at(row("frontier", "multi_room", true, 0.4, 50), "a", 2, 20), at(row("full", "multi_room", true, 0.41, 49), "a", 2, 20),
      at(row("frontier", "multi_room", true, 0.8, 6), "b", 1, 5), at(row("full", "multi_room", true, 0.6, 8), "b", 1, 5),
      at(row("frontier", "single_room", true, 1.0, 3), "c", 1, 3), at(row("full", "single_room", true, 1.0, 3), "c", 1, 3),
      at(row("full", "multi_room", false, 0.0, 60), "d", 1, 30)};  // no frontier twin: not paired
  EXPECT_EQ(splitsOf(rows[0]), (std::vector<std::string>{"multi_room", "long_horizon", "all"}));
  EXPECT_EQ(splitsOf(rows[4]), (std::vector<std::string>{"multi_room", "all"}));
  EXPECT_EQ(splitsOf(rows[6]), (std::vector<std::string>{"single_room", "all"}));
  const auto j = summaryJson(rows);
  EXPECT_EQ(j["frontier"]["long_horizon"]["episodes"].get<int>(), 2);
  EXPECT_NEAR(j["frontier"]["long_horizon"]["spl"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(j["full"]["long_horizon"]["episodes"].get<int>(), 3);
  EXPECT_NEAR(j["full"]["long_horizon"]["sr"].get<double>(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(j["full"]["long_horizon"]["spl"].get<double>(), 0.91 / 3.0, 1e-12);
  EXPECT_EQ(j["full"]["multi_room"]["episodes"].get<int>(), 4);
  const std::string md = summaryMarkdown(rows, "t");
  // long_horizon pairs: (0.2 -> 0.5) better, (0.4 -> 0.41) same; ratio 0.91 / 0.6.
  EXPECT_NE(md.find("| long_horizon | 2 | 0.300 | 0.455 | 1.52x | 1 | 1 | 0 |"), std::string::npos) << md;
  // multi_room pairs add (0.8 -> 0.6) worse: 1.4 / 1.51.
  EXPECT_NE(md.find("| multi_room | 3 | 0.467 | 0.503 | 1.08x | 1 | 1 | 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| single_room | 1 | 1.000 | 1.000 | 1.00x | 0 | 1 | 0 |"), std::string::npos) << md;
  // A split with no pairs shows no SPL (not 0.000).
  const std::vector<EpisodeRow> multi_only(rows.begin(), rows.begin() + 2);
  EXPECT_NE(summaryMarkdown(multi_only, "t").find("| single_room | 0 | - | - | - | 0 | 0 | 0 |"), std::string::npos);
  // Without the baseline there is nothing to pair.
  const std::vector<EpisodeRow> full_only(rows.begin() + 1, rows.begin() + 2);
  EXPECT_EQ(summaryMarkdown(full_only, "t").find("against frontier"), std::string::npos);
}

TEST(EvalReport, PathSplitAtTheSightingMatchesHandComputation) {
  auto seen = [](EpisodeRow r, double search, double approach_star) {
    r.search_m = search, r.approach_shortest_m = approach_star, r.view_shortest_m = search / 2;
    return r;
  };
  const std::vector<EpisodeRow> rows = {
      seen(row("frontier", "multi_room", true, 0.25, 20), 14, 4),   // 14 m of search, 6 m of approach
      seen(row("frontier", "multi_room", true, 0.5, 10), 8, 1),     // 8 + 2
      seen(row("frontier", "multi_room", false, 0.0, 30), 5, 3),    // a failure: left out
      seen(row("frontier", "multi_room", true, 0.5, 10), -1, -1),   // never sighted: left out
      seen(row("frontier", "single_room", true, 1.0, 5), 0, 5)};
  const auto j = summaryJson(rows);
  const auto& m = j["frontier"]["multi_room"]["path_split"];
  EXPECT_EQ(m["episodes"].get<int>(), 2);
  EXPECT_NEAR(m["path_length_m"].get<double>(), 15.0, 1e-12);
  EXPECT_NEAR(m["search_m"].get<double>(), 11.0, 1e-12);
  EXPECT_NEAR(m["approach_m"].get<double>(), 4.0, 1e-12);
  EXPECT_NEAR(m["approach_shortest_m"].get<double>(), 2.5, 1e-12);
  EXPECT_NEAR(m["view_shortest_m"].get<double>(), 5.5, 1e-12);
  EXPECT_EQ(j["frontier"]["all"]["path_split"]["episodes"].get<int>(), 3);
  const std::string md = summaryMarkdown(rows, "t");
  EXPECT_NE(md.find("| multi_room | frontier | 2 | 15.0 | 5.0 | 11.0 | 5.5 | 4.0 | 2.5 |"), std::string::npos) << md;
  // The columns round-trip; a file from before them loads with no sighting.
  int bad = 0;
  const auto back = readEpisodesCsv(writeText("split.csv", csvHeader() + "\n" + toCsv(rows[0]) + "\n"), &bad);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_NEAR(back[0].search_m, 14.0, 1e-3);
  EXPECT_NEAR(back[0].approach_shortest_m, 4.0, 1e-3);
  EXPECT_NEAR(back[0].view_shortest_m, 7.0, 1e-3);
  const std::string labels_header =
      "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
      "found_label,update_hz,wall_s,labels_scored,labels_correct";
  const auto old = readEpisodesCsv(
      writeText("labels_only.csv", labels_header + "\nw,tv,full,1,multi_room,1,0.5000,4.000,2.000,8.00,80,0,found,tv,50.0,1.00,4,2\n"),
      &bad);
  ASSERT_EQ(old.size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(old[0].labels_correct, 2);
  EXPECT_LT(old[0].search_m, 0.0);
}

TEST(EvalReport, RegionColumnsRoundTripAndAreSummarised) {
  EpisodeRow a = row("full", "multi_room", true, 0.4, 12.5);
  a.region_count = 6, a.region_largest_share = 0.5, a.region_ari = 0.8;
  EpisodeRow b = row("full", "single_room", true, 0.2, 9.0);
  b.region_count = 2, b.region_largest_share = 0.9, b.region_ari = -1.0;  // a world without rooms
  EpisodeRow c = row("full", "multi_room", true, 0.3, 10.0);
  c.region_count = 4, c.region_largest_share = 0.4, c.region_ari = 0.4;
  int bad = 0;
  const auto back = readEpisodesCsv(writeText("regions.csv", csvHeader() + "\n" + toCsv(a) + "\n" + toCsv(b) + "\n"), &bad);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(back[0].region_count, 6);
  EXPECT_NEAR(back[0].region_largest_share, 0.5, 1e-4);
  EXPECT_NEAR(back[0].region_ari, 0.8, 1e-4);
  EXPECT_NEAR(back[1].region_ari, -1.0, 1e-9);
  // A region column that is not a number (an interrupted write): the row is dropped and counted.
  std::string garbled = toCsv(a);
  garbled.replace(garbled.rfind(','), std::string::npos, ",x");
  EXPECT_TRUE(readEpisodesCsv(writeText("regions_garbled.csv", csvHeader() + "\n" + garbled + "\n"), &bad).empty());
  EXPECT_EQ(bad, 1);
  // Means by hand: count (6 + 2 + 4) / 3 = 4, share (0.5 + 0.9 + 0.4) / 3 = 0.6, ARI over the two
  // episodes in a world with rooms (0.8 + 0.4) / 2 = 0.6.
  const auto j = summaryJson({a, b, c, row("frontier", "multi_room", true, 0.3, 10)});
  const auto& g = j["full"]["regions"];
  EXPECT_EQ(g["episodes"].get<int>(), 3);
  EXPECT_NEAR(g["mean_count"].get<double>(), 4.0, 1e-12);
  EXPECT_NEAR(g["mean_largest_share"].get<double>(), 0.6, 1e-12);
  EXPECT_EQ(g["ari_episodes"].get<int>(), 2);
  EXPECT_NEAR(g["mean_ari"].get<double>(), 0.6, 1e-12);
  EXPECT_FALSE(j["frontier"].contains("regions"));  // no region columns: nothing to average
  const std::string md = summaryMarkdown({a, b, c}, "t");
  EXPECT_NE(md.find("| full | 3 | 4.0 | 60 % | 2 | 0.600 |"), std::string::npos) << md;
  // A file from before these columns (21 of them) loads, with no regions.
  const std::string sighting_header = csvHeader().substr(0, csvHeader().find(",region_count"));
  std::string old_row = toCsv(a);
  for (int i = 0; i < 3; ++i) old_row.erase(old_row.rfind(','));
  const auto old = readEpisodesCsv(writeText("sighting.csv", sighting_header + "\n" + old_row + "\n"), &bad);
  ASSERT_EQ(old.size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(old[0].region_count, 0);
  EXPECT_NEAR(old[0].region_ari, -1.0, 1e-9);
}

TEST(Suite, ShippedSuitesLoadAndTheLargeOneIsMultiRoom) {
  const auto dir = std::filesystem::path(USSNAV_SOURCE_DIR) / "configs/suites";
  int files = 0;
  // Generated worlds are named style-seed-rN; none may sit in two suites (wide.yaml promises
  // worlds no other suite uses, so its numbers are not the others' again).
  std::map<std::string, std::string> generated;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".yaml") continue;
    ++files;
    const Suite s = loadSuite(e.path());
    EXPECT_FALSE(s.worlds.empty()) << e.path();
    EXPECT_FALSE(s.goals.empty()) << e.path();
    for (const SuiteWorld& sw : s.worlds) {
      if (sw.kind != SuiteWorld::Kind::Generate) continue;
      const std::string key = sw.generate.style + "-" + std::to_string(sw.generate.seed) + "-r" +
                              std::to_string(sw.generate.target_rooms);
      const auto [it, fresh] = generated.emplace(key, e.path().filename().string());
      EXPECT_TRUE(fresh) << key << " in " << it->second << " and " << e.path().filename().string();
    }
  }
  EXPECT_GE(files, 4);
  EXPECT_GE(generated.size(), 28u);

  // configs/suites/large.yaml promises 16-24 rooms, a start in a hallway or corridor, and no goal
  // instance in the start room (every task multi-room).
  const Suite large = loadSuite(dir / "large.yaml");
  for (const SuiteWorld& sw : large.worlds) {
    ASSERT_EQ(sw.kind, SuiteWorld::Kind::Generate) << sw.name;
    const World w = materializeWorld(sw);
    EXPECT_GE(w.rooms.size(), 16u) << sw.name;
    EXPECT_LE(w.rooms.size(), 24u) << sw.name;
    const Room* start = w.roomAt(w.start.position.head<2>());
    ASSERT_NE(start, nullptr) << sw.name;
    EXPECT_TRUE(start->type == "hallway" || start->type == "corridor") << sw.name << ": " << start->type;
    int instances = 0;
    for (const Object& o : w.objects) {
      if (std::find(large.goals.begin(), large.goals.end(), o.category) == large.goals.end()) continue;
      ++instances;
      EXPECT_NE(o.room_id, start->id) << sw.name << ": a " << o.category << " in the start room";
    }
    EXPECT_GT(instances, 0) << sw.name;
  }
}
