// DIR/index.html of `ussnav eval` (eval/eval_index.hpp): the embedded rows and summary are the
// report's, episode folders get names without spaces, no goal text can end the script, and
// -- where node is installed -- the page's script renders, filters and sorts the rows.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/eval/eval_index.hpp"

namespace ussnav {
namespace {

EpisodeRow row(const std::string& world, const std::string& goal, const std::string& planner, bool success, double spl) {
  EpisodeRow r;
  r.world = world, r.goal = goal, r.planner = planner, r.split = "multi_room";
  r.success = success, r.spl = spl, r.path_length_m = 20.0, r.shortest_path_m = 10.0, r.time_s = 30.0;
  r.end_reason = std::string(success ? "found" : "time_budget");
  r.found_label = std::string(success ? "bed" : "");
  return r;
}

TEST(EvalIndex, PageHoldsTheRowsAndTheSummaryAndRendersThem) {
  const std::vector<EpisodeRow> rows = {row("apartment-1-r8", "somewhere to sleep", "full", true, 0.5),
                                        row("apartment-1-r8", "somewhere to sleep", "frontier", true, 0.25),
                                        row("house_3", "bed</script>x", "full", false, 0.0)};
  EXPECT_EQ(episodeFolderName(rows[0]), "apartment-1-r8_somewhere_to_sleep_full_s1");
  EXPECT_EQ(episodeFolderName(rows[2]), "house_3_bed__script_x_full_s1");
  const std::string page = evalIndexHtml(rows, {true, false, false}, "ussnav eval: test");
  size_t scripts = 0;
  for (size_t at = page.find("</script>"); at != std::string::npos; at = page.find("</script>", at + 1)) ++scripts;
  EXPECT_EQ(scripts, 2u);  // the data block's and the script's own
  const std::string open = "<script id=\"ussnav-data\" type=\"application/json\">";
  const size_t a = page.find(open), b = page.find("</script>", a);
  const auto d = nlohmann::json::parse(page.substr(a + open.size(), b - a - open.size()));
  EXPECT_EQ(d["summary"], summaryJson(rows));
  ASSERT_EQ(d["rows"].size(), 3u);
  EXPECT_EQ(d["rows"][2]["goal"], "bed</script>x");
  EXPECT_EQ(d["rows"][0]["folder"], "apartment-1-r8_somewhere_to_sleep_full_s1");
  EXPECT_TRUE(d["rows"][1]["folder"].is_null());

  std::string out;
  if (test::runCommand("command -v node", &out) != 0) GTEST_SKIP() << "node is not installed: the page's script was not run";
  const auto dir = test::tempDir("eval_index");
  writeFileAtomic(dir / "index.html", page);
  const int rc = test::runCommand("node " + std::string(USSNAV_SOURCE_DIR) + "/tests/eval/index_check.js " +
                                      (dir / "index.html").string() + " 2>&1",
                                  &out);
  ASSERT_EQ(rc, 0) << out;
  const auto r = nlohmann::json::parse(out);
  EXPECT_EQ(r["title"], "ussnav eval: test");
  EXPECT_GE(r["summary"].get<int>(), 4);  // full and frontier: multi_room and all each
  ASSERT_EQ(r["rows"].size(), 3u);
  EXPECT_EQ(r["rows"][0][0], "apartment-1-r8");
  EXPECT_EQ(r["rows"][0][5], "found bed");
  EXPECT_EQ(r["rows"][2][5], "time_budget");
  EXPECT_EQ(r["links"][0].size(), 3u);  // graph, picture, result of the saved episode
  EXPECT_EQ(r["links"][0][0], "episodes/apartment-1-r8_somewhere_to_sleep_full_s1/scene_graph.html");
  EXPECT_TRUE(r["links"][1].empty());
  EXPECT_EQ(r["count"], "3 of 3 episodes");
  ASSERT_EQ(r["failRows"].size(), 1u);
  EXPECT_EQ(r["failRows"][0][0], "house_3");
  EXPECT_EQ(r["bySpl"], nlohmann::json({"0.000", "0.250", "0.500"}));
}

}  // namespace
}  // namespace ussnav
