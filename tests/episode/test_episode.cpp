// Whole episodes in small hand-made worlds: the flight loop finds a target in the next room,
// never collides, and its SPL is the protocol's formula; bad input is rejected.

#include <gtest/gtest.h>

#include "support/paths.hpp"
#include "support/test_worlds.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/importers/procthor.hpp"

using namespace ussnav;

namespace {

Config testConfig() {
  Config cfg = defaultConfig();
  cfg.episode.max_time_s = 150.0;
  return cfg;
}

EpisodeSpec twoRoomSpec(const std::string& planner, const std::string& goal) {
  EpisodeSpec s;
  s.world = test::twoRooms(true);                      // start in room A at (2.5, 2)
  test::addObject(s.world, "bed", Vec3(8.6, 3.0, 0.3), Vec3(0.9, 0.7, 0.3));  // in room B
  test::addObject(s.world, "chair", Vec3(1.0, 0.8, 0.45), Vec3(0.25, 0.25, 0.45));  // in room A
  s.world.objects[0].room_id = s.world.rooms[1].id;
  s.world.objects[1].room_id = s.world.rooms[0].id;
  s.world_name = "two-rooms";
  s.goal = goal;
  s.planner = planner;
  s.seed = 3;
  return s;
}

}  // namespace

class EpisodePlanners : public ::testing::TestWithParam<std::string> {};

TEST_P(EpisodePlanners, FindsTheBedInTheNextRoomWithoutCollision) {
  const Config cfg = testConfig();
  const EpisodeRun run = runEpisode(twoRoomSpec(GetParam(), "bed"), cfg);
  const EpisodeResult& r = run.result;
  EXPECT_TRUE(r.success) << r.end_reason;
  EXPECT_EQ(r.end_reason, "found");
  EXPECT_EQ(r.collisions, 0);
  EXPECT_TRUE(r.multi_room);  // no bed in the start room
  ASSERT_TRUE(r.found_object.has_value());
  EXPECT_NEAR(r.found_object->position.x(), 8.6, 0.6);
  EXPECT_NEAR(r.found_object->position.y(), 3.0, 0.6);
  // SPL as DESIGN.md defines it, from the episode's own lengths.
  ASSERT_GT(r.shortest_path_m, 0.0);
  EXPECT_NEAR(r.spl, r.shortest_path_m / std::max(r.path_length_m, r.shortest_path_m), 1e-9);
  // The shortest path to a pose within 1 m of the bed from (2.5, 2) through the door at x = 5:
  // at least the straight distance to the bed's 1 m neighbourhood.
  EXPECT_GE(r.shortest_path_m, (Vec2(7.7, 2.3) - Vec2(2.5, 2.0)).norm() - 1.0 - 0.05);
  // The path split at the bed's first sighting: flown until then (search) and after it, which
  // is at least L* from where the UAV was (it ends at a success pose, up to a 0.05 m cell and
  // the 2-cell sampling of success poses); that L* is at most L* from the start plus the search
  // (the triangle inequality).
  ASSERT_GE(r.search_m, 0.0);
  EXPECT_LE(r.search_m, r.path_length_m);
  EXPECT_GE(r.sighted_s, 0.0);
  EXPECT_LE(r.sighted_s, r.time_s);
  ASSERT_GE(r.approach_shortest_m, 0.0);
  EXPECT_GE(r.path_length_m - r.search_m, r.approach_shortest_m - 0.3);
  EXPECT_LE(r.approach_shortest_m, r.shortest_path_m + r.search_m + 0.15);
  // The least search: the bed's box is 5.2 m from the start in plan, so a view within the
  // detector's 4.5 m lies at least 0.7 m away, and no farther than a pose that sees the bed from 1 m.
  EXPECT_GE(r.view_shortest_m, (Vec2(7.7, 2.3) - Vec2(2.5, 2.0)).norm() - 4.5 - 0.1);
  EXPECT_LE(r.view_shortest_m, r.shortest_path_m + 0.5);
  // Every flown position keeps the UAV radius from the ground truth.
  const GroundTruthGrid gt(twoRoomSpec(GetParam(), "bed").world, cfg.sim.gt_resolution);
  for (const TrajectorySample& s : run.trajectory) ASSERT_FALSE(gt.sphereCollides(s.pose.position, cfg.sim.uav.radius));
  EXPECT_GT(r.update_hz, 0.0);
  EXPECT_TRUE(r.stage_ms.contains("frontiers"));
  EXPECT_TRUE(r.stage_ms.contains("skeleton"));
  // Two rooms and a 1 m door: no flight path needs a detour through voxels not seen yet. Every
  // re-plan that did not end unreachable flew a planned path.
  EXPECT_GE(r.paths_planned, r.replans - r.unreachable);
  EXPECT_GT(r.paths_planned, 0);
  EXPECT_EQ(r.paths_through_unknown, 0);
  EXPECT_LE(r.paths_narrow, r.paths_planned);
}

INSTANTIATE_TEST_SUITE_P(AllPlanners, EpisodePlanners, ::testing::Values("frontier", "tsp", "full"));

TEST(Episode, SameSeedSameEpisode) {
  const Config cfg = testConfig();
  const EpisodeResult a = runEpisode(twoRoomSpec("frontier", "bed"), cfg).result;
  const EpisodeResult b = runEpisode(twoRoomSpec("frontier", "bed"), cfg).result;
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_DOUBLE_EQ(a.path_length_m, b.path_length_m);
  EXPECT_EQ(a.success, b.success);
}

TEST(Episode, GoalAbsentFromTheWorldEndsWithoutSuccess) {
  Config cfg = testConfig();
  cfg.episode.max_time_s = 60.0;
  const EpisodeResult r = runEpisode(twoRoomSpec("frontier", "toilet"), cfg).result;
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.goal_instances, 0);
  EXPECT_LT(r.shortest_path_m, 0.0);
  EXPECT_EQ(r.spl, 0.0);
  EXPECT_LT(r.search_m, 0.0);  // nothing to sight
  EXPECT_TRUE(r.end_reason == "explored" || r.end_reason == "time_budget") << r.end_reason;
  EXPECT_EQ(r.collisions, 0);
}

TEST(Episode, RejectsUnknownPlannerAndEmptyGoal) {
  const Config cfg = testConfig();
  EXPECT_THROW(runEpisode(twoRoomSpec("greedy", "bed"), cfg), InputError);
  EXPECT_THROW(runEpisode(twoRoomSpec("frontier", "  "), cfg), InputError);
}

TEST(Episode, FrontierSeenThroughADoorGetsACloserLook) {
  // ProcTHOR house_18 (a real house): the UAV starts in the bedroom; the tv is in the living
  // room beyond a door at the bedroom's far end. The frontier beyond that door is first
  // planned from a viewpoint on the bedroom side; from there the living room's side reaches
  // are out of sight, so the frontier is still open when the viewpoint is reached. Dropping it
  // then left nothing else open (the episode ended "explored" at 21.5 m, docs/eval.md);
  // episode.close_look flies to the graph node nearest to it instead, in the doorway.
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  EpisodeSpec s;
  s.world = importProcthorHouse(test::sharedData() / "procthor_houses" / "houses" / "house_18.json");
  s.world_name = "house_18";
  s.goal = "tv";
  s.planner = "frontier";
  s.seed = 1;
  Config cfg = testConfig();
  cfg.exploration.remember_known_band = true;
  cfg.exploration.open_in_visited = true;
  cfg.exploration.open_in_visited_above = 0.25;
  cfg.episode.close_look = false;
  const EpisodeResult off = runEpisode(s, cfg).result;
  std::printf("[ close_look off ] %s after %.1f m\n", off.end_reason.c_str(), off.path_length_m);
  EXPECT_EQ(off.close_looks, 0);
  cfg.episode.close_look = true;
  const EpisodeResult on = runEpisode(s, cfg).result;
  std::printf("[ close_look on ] %s after %.1f m, %d closer looks, SPL %.3f\n", on.end_reason.c_str(),
              on.path_length_m, on.close_looks, on.spl);
  EXPECT_TRUE(on.multi_room);
  EXPECT_GE(on.close_looks, 1);
  EXPECT_TRUE(on.success) << on.end_reason;
  EXPECT_EQ(on.collisions, 0);
}

TEST(Episode, LookAroundSeesTheStartRoomBeforeTheFirstPlan) {
  // The chair stands behind the UAV (bearing -141 deg from the start, facing +x; the camera
  // sees +-43.5 deg). With episode.look_around the UAV turns on the spot first: it sees the chair
  // before it flies anywhere, and flies only the approach.
  Config cfg = testConfig();
  cfg.episode.look_around = true;
  const EpisodeRun on = runEpisode(twoRoomSpec("frontier", "chair"), cfg);
  ASSERT_TRUE(on.result.success) << on.result.end_reason;
  EXPECT_FALSE(on.result.multi_room);
  const Vec3 start = on.trajectory.front().pose.position;
  size_t moved = 0;  // first sample away from the start
  while (moved < on.trajectory.size() && (on.trajectory[moved].pose.position - start).norm() < 0.05) ++moved;
  ASSERT_LT(moved, on.trajectory.size());
  double turned = 0.0;  // yaw swept on the spot before that
  for (size_t i = 1; i < moved; ++i)
    turned += std::abs(wrapAngle(on.trajectory[i].pose.yaw - on.trajectory[i - 1].pose.yaw));
  EXPECT_GT(turned, deg2rad(141.0 - 43.5)) << "left the start before the chair could be in view";
  EXPECT_LE(on.result.path_length_m, on.result.shortest_path_m + 1.0);

  cfg.episode.look_around = false;
  const EpisodeRun off = runEpisode(twoRoomSpec("frontier", "chair"), cfg);
  std::printf("[ look_around on / off ] %.2f m / %.2f m (shortest %.2f m)\n", on.result.path_length_m,
              off.result.path_length_m, on.result.shortest_path_m);
  ASSERT_TRUE(off.result.success) << off.result.end_reason;
  size_t off_moved = 0;
  while (off_moved < off.trajectory.size() && (off.trajectory[off_moved].pose.position - start).norm() < 0.05) ++off_moved;
  EXPECT_LT(off_moved, moved);  // without it the UAV sets off at once
}

namespace {
// Spots where the UAV turned full circle on the spot (a yaw sweep of at least 350 degrees with
// the position within 5 cm: look_around's three 120-degree steps), as x-y.
std::vector<Vec2> turnsOnTheSpot(const std::vector<TrajectorySample>& tr) {
  std::vector<Vec2> out;
  size_t i = 0;
  while (i < tr.size()) {
    size_t j = i + 1;
    double swept = 0.0;
    while (j < tr.size() && (tr[j].pose.position - tr[i].pose.position).norm() < 0.05)
      swept += std::abs(wrapAngle(tr[j].pose.yaw - tr[j - 1].pose.yaw)), ++j;
    if (swept >= deg2rad(350.0)) out.push_back(tr[i].pose.position.head<2>());
    i = j;
  }
  return out;
}
}  // namespace

TEST(Episode, LookAgainTurnsRoundAtViewpointsFarFromEarlierTurns) {
  // No toilet in the two rooms: the UAV explores both. With episode.look_again_m it turns round
  // at reached viewpoints at least that far from the start and from each other; without it
  // only at the start (other turns on the spot, to face a viewpoint, sweep less).
  Config cfg = testConfig();
  cfg.episode.max_time_s = 60.0;
  cfg.episode.look_around = true;
  cfg.episode.look_again_m = 2.0;
  const EpisodeRun on = runEpisode(twoRoomSpec("frontier", "toilet"), cfg);
  const std::vector<Vec2> spots = turnsOnTheSpot(on.trajectory);
  ASSERT_GE(spots.size(), 2u) << "no turn but the take-off one";
  const Vec2 start = on.trajectory.front().pose.position.head<2>();
  EXPECT_LT((spots.front() - start).norm(), 0.05);
  for (size_t a = 0; a < spots.size(); ++a)
    for (size_t b = a + 1; b < spots.size(); ++b) EXPECT_GE((spots[a] - spots[b]).norm(), 2.0 - 0.05);
  EXPECT_EQ(on.result.collisions, 0);
  cfg.episode.look_again_m = 0.0;
  const EpisodeRun off = runEpisode(twoRoomSpec("frontier", "toilet"), cfg);
  const std::vector<Vec2> off_spots = turnsOnTheSpot(off.trajectory);
  ASSERT_EQ(off_spots.size(), 1u);
  EXPECT_LT((off_spots.front() - start).norm(), 0.05);
}

TEST(Episode, AGoalSightedInAFewFramesIsApproachedAndDeclaredOnlyWhenSeenOftenEnough) {
  // From the start room the camera sees the bed through the door for a few frames of the
  // take-off turn: fewer than target_min_observations. The sighting is approached at once, with
  // no exploration target planned, and declared from the pose once seen often enough there.
  Config cfg = testConfig();
  cfg.episode.look_around = true;
  const EpisodeResult r = runEpisode(twoRoomSpec("full", "bed"), cfg).result;
  ASSERT_TRUE(r.success) << r.end_reason;
  EXPECT_EQ(r.replans, 0);
  EXPECT_LE(r.path_length_m, r.shortest_path_m + 1.0);
  // However it is approached, an object seen fewer times than that is never declared.
  cfg.episode.target_min_observations = 100000;
  cfg.episode.max_time_s = 60.0;
  const EpisodeResult never = runEpisode(twoRoomSpec("full", "bed"), cfg).result;
  EXPECT_FALSE(never.success);
  EXPECT_FALSE(never.found_object.has_value()) << never.end_reason;
  EXPECT_NE(never.end_reason, "wrong_object");
}

TEST(Episode, LookFirstApproachesTheNearestGoalSeenAllRound) {
  // Two chairs in the start room: one ahead of the UAV (in view at take-off, 2.1 m off), one
  // behind it (out of view until it turns, 1.1 m off). Approaching the first one seen left the
  // nearer one behind (the Webots apartment, "somewhere to sit": 4.1 m flown to a chair with an
  // armchair beside the start). With episode.look_first the take-off turns finish first, and
  // the nearest goal object seen all round is approached; turning costs no path.
  const auto spec = [] {
    EpisodeSpec s;
    s.world = test::twoRooms(true);  // start (2.5, 2), facing +x
    test::addObject(s.world, "chair", Vec3(4.6, 2.0, 0.45), Vec3(0.25, 0.25, 0.45));  // ahead
    test::addObject(s.world, "chair", Vec3(1.4, 2.0, 0.45), Vec3(0.25, 0.25, 0.45));  // behind
    for (Object& o : s.world.objects) o.room_id = s.world.rooms[0].id;
    s.world_name = "two-rooms";
    s.goal = "chair";
    s.planner = "frontier";
    s.seed = 3;
    return s;
  };
  Config cfg = testConfig();
  cfg.episode.look_around = true;
  cfg.episode.look_first = true;
  const EpisodeResult first = runEpisode(spec(), cfg).result;
  ASSERT_TRUE(first.success) << first.end_reason;
  ASSERT_TRUE(first.found_object.has_value());
  EXPECT_NEAR(first.found_object->position.x(), 1.4, 0.5);  // the chair behind
  cfg.episode.look_first = false;
  const EpisodeResult seen = runEpisode(spec(), cfg).result;
  ASSERT_TRUE(seen.success) << seen.end_reason;
  ASSERT_TRUE(seen.found_object.has_value());
  EXPECT_NEAR(seen.found_object->position.x(), 4.6, 0.5);  // the chair ahead, seen first
  std::printf("[ look_first on / off ] %.2f m / %.2f m (shortest %.2f m)\n", first.path_length_m, seen.path_length_m,
              first.shortest_path_m);
  EXPECT_LE(first.path_length_m, seen.path_length_m);
}
