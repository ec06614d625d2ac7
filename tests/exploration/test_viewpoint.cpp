// Viewpoints of frontiers mapped from an analytic room: safe, in known free space, and their
// gain equals a brute-force count of the frontier cells visible with the chosen yaw.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/mapping_scenes.hpp"
#include "ussnav/exploration/frontier.hpp"

using namespace ussnav;

namespace {

Intrinsics d455(int w, int h) { return Intrinsics::fromFov(w, h, deg2rad(87), deg2rad(58)); }

// Visibility written out again: range, vertical then horizontal FOV, line of sight with
// unknown voxels blocking.
int bruteGain(const RollingGrid& g, const Frontier& f, const Vec3& p, double yaw, const ExplorationConfig& cfg) {
  int n = 0;
  for (const Vec3i& k : f.cells) {
    const Vec3 c = (k.cast<double>() + Vec3::Constant(0.5)) * g.resolution();
    const Vec3 d = c - p;
    if (d.norm() > cfg.sensor_range) continue;
    if (std::abs(std::atan2(d.z(), std::hypot(d.x(), d.y()))) > deg2rad(cfg.sensor_vfov_deg) / 2) continue;
    double off = std::atan2(d.y(), d.x()) - yaw;
    off = std::atan2(std::sin(off), std::cos(off));
    if (std::abs(off) > deg2rad(cfg.sensor_hfov_deg) / 2 + 1e-12) continue;
    if (castRay(g, p, c, true).blocked) continue;
    ++n;
  }
  return n;
}

}  // namespace

TEST(Viewpoint, SafeFreeAndGainMatchesBruteForce) {
  // Two rooms joined by a door: the camera sees into the second room partly.
  const test::BoxScene scene = test::boxRoom(Vec3(-3.03, -2.87, 0.0), Vec3(7.03, 2.91, 2.73));
  const ExplorationConfig cfg;
  RollingGrid grid(GridConfig{}, Vec3(0, 0, 1.2));
  CoverageMask gcm(CoverageConfig{}, grid.resolution());
  FrontierFinder finder(cfg);
  // Viewpoints are computed when a frontier is made (or remade) and kept until its cells change:
  // each is checked against the grid of the frame that made it.
  int checked = 0, frontiers_with = 0;
  for (int i = 0; i < 6; ++i) {
    const Vec3 p(0.4 * i, 0.0, 1.2);
    grid.moveTo(p);
    grid.insertDepth(test::renderDepth(scene, d455(80, 60), test::cameraPose(p, 1.1 * i), 5.0));
    gcm.update(grid);
    const FrontierUpdate up = finder.update(grid, gcm, 0, i);
    grid.clearChanges();
    for (const int id : up.added) {
      const Frontier* f = finder.find(id);
      ASSERT_NE(f, nullptr);
      frontiers_with += !f->viewpoints.empty();
      EXPECT_LE(int(f->viewpoints.size()), cfg.max_viewpoints);
      for (const Viewpoint& v : f->viewpoints) {
        ++checked;
        EXPECT_EQ(grid.stateAt(v.position), VoxelState::Free);
        EXPECT_FALSE(grid.isInflatedOccupied(v.position, cfg.viewpoint_clearance, true));
        EXPECT_NEAR(v.position.z(), cfg.viewpoint_height, 1e-12);
        const double r = std::hypot(v.position.x() - f->centroid.x(), v.position.y() - f->centroid.y());
        EXPECT_GE(r, cfg.viewpoint_r_min - 1e-9);
        EXPECT_LE(r, cfg.viewpoint_r_max + 1e-9);
        EXPECT_GE(v.gain, cfg.min_viewpoint_gain);
        EXPECT_EQ(v.gain, bruteGain(grid, *f, v.position, v.yaw, cfg)) << "frontier " << id << " at " << v.position.transpose();
        // No sampled yaw sees more.
        for (int y = 0; y < 72; ++y) EXPECT_LE(bruteGain(grid, *f, v.position, y * kPi / 36, cfg), v.gain);
      }
    }
  }
  std::printf("%zu frontiers, %d with viewpoints, %d viewpoints checked\n", finder.frontiers().size(),
              frontiers_with, checked);
  EXPECT_GT(checked, 5);
}

TEST(Viewpoint, UnsafeAndUnknownPositionsRejected) {
  const test::BoxScene scene = test::boxRoom(Vec3(-3.03, -2.87, 0.0), Vec3(3.03, 2.91, 2.73));
  RollingGrid grid(GridConfig{}, Vec3(0, 0, 1.2));
  grid.insertDepth(test::renderDepth(scene, d455(80, 60), test::cameraPose(Vec3(0, 0, 1.2), 0.0), 5.0));
  const ExplorationConfig cfg;
  EXPECT_TRUE(viewpointSafe(grid, Vec3(1.0, 0.0, 1.2), cfg));    // seen free, in front
  EXPECT_FALSE(viewpointSafe(grid, Vec3(-1.5, 0.0, 1.2), cfg));  // behind the camera: unknown
  EXPECT_FALSE(viewpointSafe(grid, Vec3(2.9, 0.0, 1.2), cfg));   // 0.13 m from the east wall
  EXPECT_FALSE(viewpointSafe(grid, Vec3(20.0, 0.0, 1.2), cfg));  // outside the window
}

// An empty window is all unknown: the volume is the field of view's cone, hfov x 2 sin(vfov/2)
// x R^3 / 3, up to the ray discretisation; the band keeps only the voxels whose centre lies in it.
TEST(Viewpoint, UnknownVolumeOfAnEmptyWindowIsTheViewCone) {
  RollingGrid grid(GridConfig{}, Vec3(0, 0, 1.2));
  ExplorationConfig cfg;
  cfg.sensor_range = 3.0;
  cfg.band_z_min = -10.0;
  cfg.band_z_max = 10.0;
  const double cone = deg2rad(cfg.sensor_hfov_deg) * 2 * std::sin(deg2rad(cfg.sensor_vfov_deg) / 2) * 27.0 / 3.0;
  const double v = visibleUnknownVolume(grid, Vec3(0.05, 0.05, 1.25), 0.3, cfg);
  EXPECT_NEAR(v, cone, 0.02 * cone);
  cfg.band_z_min = 1.3;  // voxel centres from 1.35 up: the upper half of the cone, less a slab
  const double upper = visibleUnknownVolume(grid, Vec3(0.05, 0.05, 1.25), 0.3, cfg);
  EXPECT_LT(upper, 0.5 * cone);
  EXPECT_GT(upper, 0.35 * cone);
}

// A mapped room with a door in its east wall onto space never seen: looking at the door shows
// the unknown room beyond; looking at a wall of the same room shows next to nothing.
TEST(Viewpoint, UnknownVolumeSeesThroughADoorNotThroughAWall) {
  test::BoxScene scene;  // interior x in [-3, 0.5], y in [-2.5, 2.5], z in [0, 2.6]; door y in [-0.5, 0.5]
  const double w = 0.5;
  scene.solids.push_back(Aabb::of(Vec3(-3.5, -3.0, -w), Vec3(6.0, 3.0, 0.0)));        // floor
  scene.solids.push_back(Aabb::of(Vec3(-3.5, -3.0, 2.6), Vec3(6.0, 3.0, 2.6 + w)));   // ceiling
  scene.solids.push_back(Aabb::of(Vec3(-3.5, -3.0, 0.0), Vec3(1.0, -2.5, 2.6)));      // south
  scene.solids.push_back(Aabb::of(Vec3(-3.5, 2.5, 0.0), Vec3(1.0, 3.0, 2.6)));        // north
  scene.solids.push_back(Aabb::of(Vec3(-3.5, -2.5, 0.0), Vec3(-3.0, 2.5, 2.6)));      // west
  scene.solids.push_back(Aabb::of(Vec3(0.5, -2.5, 0.0), Vec3(1.0, -0.5, 2.6)));       // east, south of the door
  scene.solids.push_back(Aabb::of(Vec3(0.5, 0.5, 0.0), Vec3(1.0, 2.5, 2.6)));         // east, north of the door
  scene.solids.push_back(Aabb::of(Vec3(0.5, -0.5, 2.1), Vec3(1.0, 0.5, 2.6)));        // lintel
  RollingGrid grid(GridConfig{}, Vec3(1.0, 0.0, 1.2));  // the window reaches x = 5
  // Full turns at five places with a 2.5 m depth range: the room is known, the next one is
  // not (no-return rays clear 2.5 m: through the door only its first metre or so).
  for (const Vec3& c : {Vec3(-1.5, 0.0, 1.2), Vec3(-2.2, -1.6, 1.2), Vec3(-2.2, 1.6, 1.2), Vec3(-0.3, -1.6, 1.2),
                       Vec3(-0.3, 1.6, 1.2)})
    for (int i = 0; i < 12; ++i)
      grid.insertDepth(test::renderDepth(scene, d455(80, 60), test::cameraPose(c, i * kPi / 6), 2.5));
  ExplorationConfig cfg;
  const Vec3 p(-1.0, 0.0, 1.2);
  ASSERT_EQ(grid.stateAt(p), VoxelState::Free);
  ASSERT_EQ(grid.stateAt(Vec3(3.0, 0.0, 1.2)), VoxelState::Unknown);
  const double door = visibleUnknownVolume(grid, p, 0.0, cfg);
  const double wall = visibleUnknownVolume(grid, p, kPi / 2, cfg);
  std::printf("unknown volume: towards the door %.2f m^3, towards the north wall %.2f m^3\n", door, wall);
  EXPECT_GT(door, 3.0);
  EXPECT_LT(wall, 0.1 * door);
}
