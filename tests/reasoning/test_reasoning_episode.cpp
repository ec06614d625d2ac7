// The coarse level inside whole episodes: free-text instructions, and proof that the reasoner
// reads the scene graph only (misleading ground-truth room labels change nothing).

#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/reasoning/region_semantics.hpp"
#include "ussnav/reasoning/scene_queries.hpp"

using namespace ussnav;

namespace {

// Room A (start) holds a fridge and a stove, room B a bed and a nightstand.
EpisodeSpec spec(const std::string& goal, const std::string& type_a, const std::string& type_b) {
  EpisodeSpec s;
  s.world = test::twoRooms(true);
  s.world.rooms[0].type = type_a;
  s.world.rooms[1].type = type_b;
  const int fridge = test::addObject(s.world, "fridge", Vec3(0.6, 3.3, 0.9), Vec3(0.35, 0.35, 0.9));
  const int stove = test::addObject(s.world, "stove", Vec3(3.5, 3.5, 0.45), Vec3(0.35, 0.3, 0.45));
  const int bed = test::addObject(s.world, "bed", Vec3(8.6, 3.0, 0.3), Vec3(0.9, 0.7, 0.3));
  const int stand = test::addObject(s.world, "nightstand", Vec3(9.5, 1.0, 0.3), Vec3(0.25, 0.25, 0.3));
  for (auto& o : s.world.objects) o.room_id = (o.id == bed || o.id == stand) ? s.world.rooms[1].id : s.world.rooms[0].id;
  (void)fridge, (void)stove;
  s.world_name = "two-rooms";
  s.goal = goal;
  s.planner = "full";
  s.seed = 5;
  return s;
}

Config testConfig() {
  Config cfg = defaultConfig();
  cfg.episode.max_time_s = 150.0;
  cfg.reasoning.reasoner = "builtin";
  // No look around at take-off: from the start room it sees the bed through the door, and a
  // sighting is approached at once, with no region to choose.
  cfg.episode.look_around = false;
  return cfg;
}

}  // namespace

TEST(ReasoningEpisode, FreeTextInstructionFindsTheBed) {
  const EpisodeRun run = runEpisode(spec("somewhere to sleep", "kitchen", "bedroom"), testConfig());
  const EpisodeResult& r = run.result;
  EXPECT_TRUE(r.success) << r.end_reason;
  ASSERT_TRUE(r.found_object.has_value());
  EXPECT_EQ(r.found_object->label, "bed");
  EXPECT_EQ(r.reasoning["interpreted"], "functional");
  EXPECT_EQ(r.reasoning["targets"][0], "bed");
  EXPECT_GT(r.reasoning["decisions"].get<int>(), 0);
  EXPECT_EQ(r.reasoner_fallbacks, 0);
  // The saved graph carries the reasoner's region labels: the room of the bed reads as a bedroom
  // (bed and nightstand; the start room may be left before its fridge and stove are seen).
  const auto sem = graphSemantics(run.graph, nullptr);
  EXPECT_EQ(sem.at(regionAt(run.graph, Vec3(8.6, 3.0, 1.2))).label, "bedroom");
  // ... and the evaluation scores it against the world's rooms (result.json region_labels).
  EXPECT_GE(r.labels_correct, 1);
  EXPECT_EQ(r.region_labels["correct"].get<int>(), r.labels_correct);
  EXPECT_EQ(r.region_labels["scored"].get<int>(), r.labels_scored);
  // ... and the regions themselves against the rooms (result.json regions).
  EXPECT_EQ(r.region_count, int(run.graph.regions.size()));
  EXPECT_EQ(r.regions["count"].get<int>(), r.region_count);
  EXPECT_GT(r.region_largest_share, 0.0);
  EXPECT_LE(r.region_largest_share, 1.0);
  // Two rooms joined by one door: two regions, split at the door.
  EXPECT_EQ(r.region_count, 2);
  EXPECT_GT(r.region_ari, 0.9);
  EXPECT_NEAR(r.regions["ari"].get<double>(), r.region_ari, 1e-12);
}

TEST(ReasoningEpisode, MisleadingGroundTruthRoomLabelsChangeNothing) {
  const Config cfg = testConfig();
  const EpisodeResult a = runEpisode(spec("bed", "kitchen", "bedroom"), cfg).result;
  const EpisodeResult b = runEpisode(spec("bed", "bedroom", "kitchen"), cfg).result;  // lies
  EXPECT_TRUE(a.success);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_DOUBLE_EQ(a.path_length_m, b.path_length_m);
  EXPECT_EQ(a.replans, b.replans);
  EXPECT_EQ(a.reasoning["decisions"], b.reasoning["decisions"]);
  EXPECT_EQ(a.success, b.success);
  // Only the evaluation reads the room types: the same labels now score worse.
  EXPECT_GT(a.labels_correct, b.labels_correct);
}

TEST(ReasoningEpisode, OracleReasonerDrivesTheFullPlannerInAnEpisode) {
  Config cfg = testConfig();
  cfg.reasoning.reasoner = "oracle";  // evaluation only: reads where the bed is
  const EpisodeResult r = runEpisode(spec("bed", "kitchen", "bedroom"), cfg).result;
  EXPECT_TRUE(r.success) << r.end_reason;
  EXPECT_EQ(r.reasoning["reasoner"], "oracle");
  EXPECT_GT(r.reasoning["decisions"].get<int>(), 0);
  EXPECT_EQ(r.reasoner_fallbacks, 0);
}
