// flyRoute: a route whose straight legs graze a door jamb (as the legs between a saved graph's
// polyhedron centres do) is flown on the live map without touching it, while following the
// same legs blindly collides; a route into a room with no door stops without a collision.

#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/episode/route_flight.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/uav.hpp"

using namespace ussnav;

namespace {

constexpr double kZ = 1.2;

// Office x in [0, 5], kitchen x in [5, 10], y in [0, 4]; the door in the wall x = 5 spans
// y in [1.5, 2.5]. The middle leg runs along the door's lower jamb.
std::vector<Vec3> grazingRoute() {
  return {Vec3(2.5, 2.0, kZ), Vec3(4.4, 1.5, kZ), Vec3(5.6, 1.5, kZ), Vec3(8.0, 1.0, kZ)};
}

Pose startAt(const Vec3& p) {
  Pose s;
  s.position = p;
  return s;
}

}  // namespace

TEST(RouteFlight, KeepsClearOfADoorJambThatTheRouteGrazes) {
  const World world = test::twoRooms(true);
  const Config cfg;
  const auto route = grazingRoute();
  {  // The legs flown blindly hit the jamb: the route is a real test.
    const Simulator sim(world, cfg, 1);
    Uav blind(cfg.sim.uav, startAt(route.front()));
    blind.setPath(route);
    for (int i = 0; i < 400 && !blind.pathDone(); ++i)
      if (!blind.step(sim.groundTruth(), 0.1)) break;
    ASSERT_GT(blind.collisions(), 0);
  }
  Simulator sim(world, cfg, 1);
  const RouteFlight f = flyRoute(sim, cfg, startAt(route.front()), route);
  EXPECT_TRUE(f.arrived) << f.end_reason;
  EXPECT_EQ(f.end_reason, "arrived");
  EXPECT_EQ(f.collisions, 0);
  EXPECT_LE((f.final_pose.position - route.back()).norm(), cfg.episode.goal_tolerance + 0.2);
  EXPECT_GE(f.legs, 1);
  // Not much longer than the route itself (about 6 m).
  EXPECT_LT(f.path_length_m, 9.0);
  EXPECT_GT(f.final_pose.position.x(), 5.0);  // in the kitchen
}

TEST(RouteFlight, ARouteThroughAWallStopsWithoutACollision) {
  const World world = test::twoRooms(false);
  Config cfg;
  // One margin on the ladder and a short stall: every failed search is a voxel A* over the window.
  cfg.episode.clearance = cfg.sim.uav.radius + 0.05;
  RouteFlightOptions opt;
  opt.stall_s = 1.0;
  Simulator sim(world, cfg, 1);
  const RouteFlight f = flyRoute(sim, cfg, startAt(Vec3(2.5, 2.0, kZ)), {Vec3(2.5, 2.0, kZ), Vec3(8.0, 2.0, kZ)}, opt);
  EXPECT_FALSE(f.arrived);
  EXPECT_EQ(f.end_reason, "no_safe_path");
  EXPECT_EQ(f.collisions, 0);
  EXPECT_LT(f.final_pose.position.x(), 5.0);
  EXPECT_THROW(flyRoute(sim, cfg, startAt(Vec3(2.5, 2.0, kZ)), {}), InputError);
}
