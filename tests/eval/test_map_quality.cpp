// skeletonQuality on a real run: a Mapper flown through the two-room world, its graph measured
// against the ground truth (free-space coverage, navigable coverage, path success).

#include <cstdio>
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
  cfg.skeleton.satellite_fill = false;  // the core graph alone leaves the wall-side band
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

TEST(MapQuality, SatellitesCoverMoreWithTheSameRegions) {
  const World w = test::twoRooms(true);
  const double z = 1.2, radius = 0.25;
  struct Run {
    std::unique_ptr<Mapper> mapper;
    SkeletonQuality q;
  };
  auto fly = [&](bool satellites) {
    Config cfg;
    cfg.skeleton.satellite_fill = satellites;
    Simulator sim(w, cfg, 3);
    auto det = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), 3);
    Run run{std::make_unique<Mapper>(cfg, MapperOptions{}, std::move(det)), {}};
    ObservedFreeSpace observed(cfg.mapping.grid.resolution, z - 0.25, z + 0.25);
    double t = 0.0;
    for (int i = 0; i < 30; ++i) {
      SensedFrame f = sim.sense(Pose{Vec3(1.0 + 8.0 * i / 30.0, 2.0, z), 0.0}, t);
      run.mapper->process({f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t});
      observed.update(run.mapper->grid());
      t += 0.2;
    }
    const GtPlanner planner(sim.groundTruth(), w, z, radius);
    run.q = skeletonQuality(run.mapper->graph(), run.mapper->grid(), sim.groundTruth(), planner, observed, radius,
                            40, 7);
    return run;
  };
  const Run core = fly(false), with = fly(true);
  const ConnectivityGraph &gc = core.mapper->graph(), &gw = with.mapper->graph();
  int satellites = 0;
  for (const ScgNode& n : gw.nodes()) satellites += n.satellite;
  ASSERT_GT(satellites, 0);
  EXPECT_EQ(gw.size(), gc.size() + size_t(satellites));
  std::printf("coverage %.3f -> %.3f, navigable %.3f -> %.3f, nodes %zu + %d satellites\n",
              core.q.free_space_coverage, with.q.free_space_coverage, core.q.navigable_coverage,
              with.q.navigable_coverage, gc.size(), satellites);
  EXPECT_GT(with.q.free_space_coverage, core.q.free_space_coverage + 0.02);
  EXPECT_GT(with.q.navigable_coverage, core.q.navigable_coverage);
  EXPECT_EQ(with.q.colliding, 0);
  EXPECT_GE(with.q.path_success, core.q.path_success);

  // The core nodes are the same (in order) and keep the same regions; every satellite has the
  // region of one of its neighbours.
  const RegionPartitioner &rc = core.mapper->regions(), &rw = with.mapper->regions();
  EXPECT_EQ(rw.regions().size(), rc.regions().size());
  size_t k = 0;
  for (const ScgNode& n : gw.nodes()) {
    if (n.satellite) {
      bool shared = false;
      for (int nb : gw.neighbors(n.id)) shared |= rw.regionOf(nb) == rw.regionOf(n.id);
      EXPECT_TRUE(shared) << "satellite " << n.id;
      continue;
    }
    ASSERT_LT(k, gc.size());
    EXPECT_EQ(n.center, gc.node(int(k)).center);
    EXPECT_EQ(rw.regionOf(n.id), rc.regionOf(int(k))) << "node " << n.id;
    ++k;
  }
}

}  // namespace
}  // namespace ussnav
