#include <gtest/gtest.h>

#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/gt_paths.hpp"

using namespace ussnav;

// Every room of a generated world is reachable from every other on the ground-truth grid, for
// a UAV of 0.25 m radius at 1.2 m: doors are cut, wide enough, and not blocked by furniture.
TEST(GeneratedWorlds, EveryRoomReachableOnTheGroundTruthGrid) {
  for (const char* style : {"office", "apartment"})
    for (uint64_t seed : {1, 2, 3}) {
      GeneratorParams p;
      p.style = style;
      p.seed = seed;
      const World w = generateWorld(p);
      const GroundTruthGrid gt(w, 0.05);
      const GtPlanner planner(gt, w, 1.2, 0.25);
      EXPECT_TRUE(planner.allRoomsConnected(w)) << style << " seed " << seed;
      // And the start pose is free.
      EXPECT_TRUE(planner.freeAt(w.start.position.head<2>())) << style << " seed " << seed;
    }
}
