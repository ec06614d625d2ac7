// skeletonQuality on a real run: a Mapper flown through the two-room world, its graph measured
// against the ground truth (free-space coverage, navigable coverage, path success).

#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/eval/map_quality.hpp"
#include "ussnav/perception/oracle_detector.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/sim/simulator.hpp"

namespace ussnav {
namespace {

TEST(MapQuality, CoverageCountsObservedFreeVoxelsAndTheNavigableOnes) {
  const World w = test::twoRooms(true);  // rooms [0,5]x[0,4] and [5,10]x[0,4], a door between
  Config cfg;
  Simulator sim(w, cfg, 3);
  auto det = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), 3);
  Mapper mapper(cfg, MapperOptions{}, std::move(det));
  const double z = 1.2, radius = 0.25;
  ObservedFreeSpace observed(cfg.mapping.grid.resolution, z - 0.25, z + 0.25);
  double t = 0.0;
  for (int i = 0; i < 30; ++i) {
    const Pose pose{Vec3(1.0 + 8.0 * i / 30.0, 2.0, z), 0.0};
    SensedFrame f = sim.sense(pose, t);
    mapper.process({f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
    observed.update(mapper.grid());
    t += 0.2;
  }
  const GtPlanner planner(sim.groundTruth(), w, z, radius);
  const SkeletonQuality q = skeletonQuality(mapper.graph(), mapper.grid(), sim.groundTruth(), planner, observed,
                                            radius, 40, 7);
  ASSERT_GT(q.observed_free_voxels, 100);
  // Navigable voxels: observed free ones with no ground-truth obstacle within the radius.
  const std::vector<Vec3> free = observed.freeCenters();
  int navigable = 0, covered = 0, nav_covered = 0;
  for (const Vec3& p : free) {
    const bool in = mapper.graph().containingNode(p) >= 0;
    covered += in;
    if (sim.groundTruth().sphereCollides(p, radius)) continue;
    ++navigable;
    nav_covered += in;
  }
  EXPECT_EQ(q.navigable_voxels, navigable);
  EXPECT_GT(navigable, 0);
  EXPECT_LT(navigable, q.observed_free_voxels);  // the wall-side band is left out
  EXPECT_DOUBLE_EQ(q.free_space_coverage, double(covered) / double(free.size()));
  EXPECT_DOUBLE_EQ(q.navigable_coverage, double(nav_covered) / double(navigable));
  // Hulls miss wall corners and wall-side wedges more than the middle of the rooms.
  EXPECT_GT(q.navigable_coverage, q.free_space_coverage + 0.02);
  // Both rooms are joined through the door: pairs find collision-free paths.
  EXPECT_EQ(q.pairs, 40);
  EXPECT_EQ(q.colliding, 0);
  EXPECT_GE(q.path_success, 0.9);
}

}  // namespace
}  // namespace ussnav
