// CameraCoverage on an analytic room: the LiDAR makes the floor area known, the camera only
// marks what lies in its field of view, and the unseen rest becomes patches with viewpoints
// that look at it; once the camera has looked everywhere no patch is left.

#include <gtest/gtest.h>

#include <cmath>

#include "support/mapping_scenes.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/exploration/camera_coverage.hpp"

using namespace ussnav;

namespace {

struct Room {
  test::BoxScene scene = test::boxRoom(Vec3(0, 0, 0), Vec3(6.0, 4.0, 2.6), 0.2, false);
  Vec3 centre{3.0, 2.0, 1.2};
  RollingGrid grid{GridConfig{}, Vec3(3.0, 2.0, 1.2)};
  Room() { grid.insertScan(test::renderScan(scene, centre, 40000, -60, 60, 40.0)); }
  DepthFrame look(double yaw) const {
    return test::renderDepth(scene, Intrinsics::fromFov(160, 120, deg2rad(87), deg2rad(58)),
                             test::cameraPose(centre, yaw), 5.0);
  }
};

}  // namespace

TEST(CameraCoverage, KnownIsTheFreeFloorAreaAndTheCameraSeesOnlyItsFieldOfView) {
  Room r;
  ExplorationConfig cfg;
  CameraCoverage cov(cfg, 1.2);
  cov.updateKnown(r.grid);
  // The 6 x 4 m room, within a cell's size at each wall.
  EXPECT_NEAR(cov.knownArea(), 24.0, 2.5);
  EXPECT_EQ(cov.seenKnownArea(), 0.0);
  cov.updateSeen(r.look(0.0));  // facing +x
  // Ahead (x = 5) is seen, behind (x = 1) is not.
  EXPECT_TRUE(cov.isSeen(cov.cellOf(Vec2(5.0, 2.0))));
  EXPECT_FALSE(cov.isSeen(cov.cellOf(Vec2(1.0, 2.0))));
  // Half-angle 43.5 deg: at x = 4.6 the view spans y = 2 +- 1.5; at x = 3.5 it misses y = 3.7.
  EXPECT_TRUE(cov.isSeen(cov.cellOf(Vec2(4.6, 2.5))));
  EXPECT_FALSE(cov.isSeen(cov.cellOf(Vec2(3.5, 3.7))));
  EXPECT_GT(cov.seenKnownArea(), 4.0);
  EXPECT_LT(cov.seenKnownArea(), 0.6 * cov.knownArea());
}

TEST(CameraCoverage, UnseenPatchesHaveViewpointsFacingThemAndVanishOnceSeen) {
  Room r;
  ExplorationConfig cfg;
  CameraCoverage cov(cfg, 1.2);
  cov.updateKnown(r.grid);
  cov.updateSeen(r.look(0.0));
  const auto patches = cov.patches();
  ASSERT_FALSE(patches.empty());
  int with_view = 0;
  for (const UnseenPatch& p : patches) {
    ASSERT_GE(int(p.cells.size()), cfg.unseen_min_cells);
    for (const Vec2i& c : p.cells) {
      EXPECT_TRUE(cov.isKnown(c));
      EXPECT_FALSE(cov.isSeen(c));
    }
    for (const Viewpoint& v : p.viewpoints) {
      ++with_view;
      // Inside the room, at flight height, facing the patch centroid.
      EXPECT_GT(v.position.x(), 0.0);
      EXPECT_LT(v.position.x(), 6.0);
      EXPECT_DOUBLE_EQ(v.position.z(), 1.2);
      const Vec2 to = p.centroid.head<2>() - v.position.head<2>();
      if (to.norm() > 1e-6) {
        EXPECT_NEAR(std::remainder(std::atan2(to.y(), to.x()) - v.yaw, 2 * kPi), 0.0, 1e-9);
      }
      EXPECT_GE(v.gain, 1);
    }
  }
  EXPECT_GT(with_view, 0);
  // Look the other three ways: only the disc under the UAV is left, where no ray of a level
  // camera gets 0.6 m below flight height (closer than 0.6 / tan(29 deg) = 1.08 m).
  for (double yaw : {kPi / 2, kPi, -kPi / 2}) cov.updateSeen(r.look(yaw));
  EXPECT_GT(cov.seenKnownArea(), cov.knownArea() - kPi * 1.3 * 1.3);
  for (const UnseenPatch& p : cov.patches())
    for (const Vec2i& c : p.cells) EXPECT_LT((cov.centerOf(c) - r.centre).norm(), 1.4);
}

TEST(CameraCoverage, AbandonedCellsAreNoTargetButStayUnseen) {
  Room r;
  CameraCoverage cov(ExplorationConfig{}, 1.2);
  cov.updateKnown(r.grid);
  const double seen = cov.seenKnownArea();
  for (const UnseenPatch& p : cov.patches()) cov.abandon(p.cells);
  EXPECT_TRUE(cov.patches().empty());
  EXPECT_EQ(cov.seenKnownArea(), seen);
}

TEST(CameraCoverage, RejectsBadParameters) {
  ExplorationConfig cfg;
  cfg.seen_resolution = 0.0;
  EXPECT_THROW(CameraCoverage(cfg, 1.2), InputError);
}
