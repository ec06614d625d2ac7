#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include "support/test_worlds.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/sim/sensors.hpp"
#include "ussnav/sim/uav.hpp"

using namespace ussnav;

namespace {
Vec3 backProject(const DepthFrame& f, int u, int v) {
  const double z = f.depth[size_t(v) * f.K.width + u];
  const Vec3 pc((u - f.K.cx) / f.K.fx * z, (v - f.K.cy) / f.K.fy * z, z);
  return f.T_world_camera * pc;
}
// The 6 x 4 m box room of the tests below (walls 0.1 m thick: inner faces x = 5.95, y = 0.05 / 3.95).
const GroundTruthGrid& boxRoomTruth() {
  static const World w = test::boxRoom(6, 4);
  static const GroundTruthGrid gt(w, 0.05);
  return gt;
}
}  // namespace

TEST(DepthCamera, DepthMatchesWallWithinOneVoxel) {
  World w = test::boxRoom(6, 4);
  GroundTruthGrid gt(w, 0.05);
  CameraConfig cc;
  cc.max_range = 8.0;
  DepthCamera cam(cc);
  const Pose pose{Vec3(2.0, 2.0, 1.4), 0.0};  // facing +x: the wall's inner face is x = 5.95
  const DepthFrame f = cam.render(gt, pose);
  int checked = 0;
  for (int v : {0, 30, 60, 90, 119})
    for (int u : {0, 40, 80, 120, 159}) {
      const float z = f.depth[size_t(v) * f.K.width + u];
      ASSERT_GT(z, 0.0f) << u << "," << v;
      const Vec3 p = backProject(f, u, v);
      // Points on the far wall (not floor/ceiling/side walls) land on x = 5.95 within a voxel.
      if (p.z() > 0.05 && p.z() < 2.75 && p.y() > 0.1 && p.y() < 3.9) {
        EXPECT_NEAR(p.x(), 5.95, 0.05 * 1.8) << u << "," << v;
        ++checked;
      }
    }
  EXPECT_GE(checked, 8);
  // The centre pixel is exactly the z-depth to the wall.
  EXPECT_NEAR(f.depth[size_t(60) * f.K.width + 80], 3.95, 0.06);
}

// max_range bounds the z-depth (frame.hpp), not the range along the ray: off-axis pixels see
// a wall whose z-depth is within max_range even where their range is not.
TEST(DepthCamera, RangeLimitIsZDepthSoEveryPixelFacingANearWallReturns) {
  const GroundTruthGrid& gt = boxRoomTruth();
  CameraConfig cc;
  cc.max_range = 4.6;
  DepthCamera cam(cc);
  // Facing +x, the far wall's inner face (x = 5.95) at z-depth 4.5; pixels more than 12 deg off
  // the axis meet it beyond 4.6 m of range. Every other surface in view is nearer.
  const DepthFrame f = cam.render(gt, Pose{Vec3(1.45, 2.0, 1.4), 0.0});
  int far_wall_off_axis = 0;
  for (int v = 0; v < f.K.height; ++v)
    for (int u = 0; u < f.K.width; ++u) {
      const float z = f.depth[size_t(v) * f.K.width + u];
      ASSERT_TRUE(std::isfinite(z) && z > 0.0f && z <= 4.6f) << u << "," << v << ": " << z;
      const Vec3 p = backProject(f, u, v);
      const double range = (p - Vec3(1.45, 2.0, 1.4)).norm();
      if (p.x() > 5.8 && range > 4.6) ++far_wall_off_axis;
    }
  EXPECT_GT(far_wall_off_axis, 1000);
}

// Too close to measure is -inf (REP 117), never 0: 0 would mean "nothing within range".
TEST(DepthCamera, AWallNearerThanMinRangeIsTooCloseNotNoReturn) {
  const GroundTruthGrid& gt = boxRoomTruth();
  CameraConfig cc;  // min_range 0.2
  DepthCamera cam(cc);
  const DepthFrame f = cam.render(gt, Pose{Vec3(5.8, 2.0, 1.4), 0.0});  // 0.15 m from the wall face
  const float centre = f.depth[size_t(60) * f.K.width + 80];
  EXPECT_TRUE(std::isinf(centre) && centre < 0) << centre;
  EXPECT_EQ(std::count(f.depth.begin(), f.depth.end(), 0.0f), 0);
}

// The camera feeding the occupancy grid (episode.fuse_depth) must never free space behind a
// wall. With the range limit taken as a range, off-axis pixels reported "no return" and the
// grid carved them free to z-depth max_range, up to 0.4 m past this wall.
TEST(DepthCamera, FusedIntoTheGridItFreesNothingBehindAWall) {
  const GroundTruthGrid& gt = boxRoomTruth();
  CameraConfig cc;
  cc.max_range = 4.6;
  DepthCamera cam(cc);
  const Vec3 p(1.45, 2.0, 1.4);
  RollingGrid grid(GridConfig{}, p + Vec3(3.0, 0.0, 0.0));  // window x in [0.45, 8.45)
  for (double yaw : {-0.3, 0.0, 0.3}) grid.insertDepth(cam.render(gt, Pose{p, yaw}));
  int free_inside = 0, free_behind = 0;
  for (int x = 5; x < 84; ++x)
    for (int y = -3; y < 44; ++y)
      for (int z = 2; z < 26; ++z) {
        const Vec3i k(x, y, z);
        if (grid.state(k) != VoxelState::Free) continue;
        // Beyond the walls' outer faces (x = 6.05, y = -0.05 and 4.05): x >= 6.1, y < -0.1, y >= 4.1.
        (x >= 61 || y <= -2 || y >= 41 ? free_behind : free_inside) += 1;
      }
  EXPECT_GT(free_inside, 5000);
  EXPECT_EQ(free_behind, 0);
}

TEST(DepthCamera, InstanceIdsAreExactlyTheObjectsInView) {
  World w = test::twoRooms(true);
  const int in_view = test::addObject(w, "chair", Vec3(4.0, 2.0, 0.5), Vec3(0.25, 0.25, 0.5));
  const int behind = test::addObject(w, "sofa", Vec3(0.8, 2.0, 0.4), Vec3(0.4, 0.8, 0.4));      // behind the camera
  const int other_room = test::addObject(w, "bed", Vec3(7.5, 0.6, 0.3), Vec3(0.5, 0.3, 0.3));  // hidden by the wall
  const int far_away = test::addObject(w, "tv", Vec3(9.5, 2.0, 1.2), Vec3(0.1, 0.5, 0.3));     // through the door, beyond range
  GroundTruthGrid gt(w, 0.05);
  CameraConfig cc;  // 5 m range
  DepthCamera cam(cc);
  const DepthFrame f = cam.render(gt, Pose{Vec3(2.0, 2.0, 1.2), 0.0});
  std::set<int> seen;
  for (uint16_t id : f.instance)
    if (id) seen.insert(id);
  EXPECT_TRUE(seen.count(in_view));
  EXPECT_FALSE(seen.count(behind));
  EXPECT_FALSE(seen.count(other_room));
  EXPECT_FALSE(seen.count(far_away));
  // With a longer range the TV through the door comes into view.
  cc.max_range = 10.0;
  DepthCamera far_cam(cc);
  const DepthFrame f2 = far_cam.render(gt, Pose{Vec3(2.0, 2.0, 1.2), 0.0});
  std::set<int> seen2(f2.instance.begin(), f2.instance.end());
  EXPECT_TRUE(seen2.count(far_away));
  EXPECT_FALSE(seen2.count(other_room));
}

TEST(DepthCamera, NoiseAndDropoutAreSeededAndDeterministic) {
  World w = test::boxRoom();
  GroundTruthGrid gt(w, 0.05);
  CameraConfig cc;
  cc.noise_std = 0.02;
  cc.dropout = 0.1;
  DepthCamera a(cc, 7), b(cc, 7), c(cc, 8);
  const Pose pose{Vec3(2, 2, 1.2), 0.3};
  const auto fa = a.render(gt, pose), fb = b.render(gt, pose), fc = c.render(gt, pose);
  // Bitwise (NaN != NaN as floats).
  auto same = [](const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
  };
  EXPECT_TRUE(same(fa.depth, fb.depth));
  EXPECT_FALSE(same(fa.depth, fc.depth));
  // A dropped pixel is invalid (NaN), not "no return": nothing is carved through it.
  const auto lost = std::count_if(fa.depth.begin(), fa.depth.end(), [](float d) { return std::isnan(d); });
  EXPECT_NEAR(double(lost) / fa.depth.size(), 0.1, 0.03);
  EXPECT_EQ(std::count(fa.depth.begin(), fa.depth.end(), 0.0f), 0);
}

TEST(Lidar, PointsLieOnSurfacesWithinTheBand) {
  World w = test::twoRooms(true);
  GroundTruthGrid gt(w, 0.05);
  LidarConfig lc;
  lc.points_per_scan = 5000;
  Lidar lidar(lc);
  const Pose pose{Vec3(2.5, 2.0, 1.2), 0.0};
  const PointCloudScan s = lidar.scan(gt, pose);
  EXPECT_GT(s.points.size(), 4500u);  // closed rooms: nearly every ray returns
  for (const auto& pf : s.points) {
    const Vec3 p = pf.cast<double>();
    // Within one voxel of an occupied voxel.
    bool near = false;
    for (int dz = -1; dz <= 1 && !near; ++dz)
      for (int dy = -1; dy <= 1 && !near; ++dy)
        for (int dx = -1; dx <= 1 && !near; ++dx) near = gt.occupiedAt(p + Vec3(dx, dy, dz) * 0.05);
    ASSERT_TRUE(near) << p.transpose();
    const Vec3 d = (p - s.origin).normalized();
    const double elev = rad2deg(std::asin(d.z()));
    EXPECT_GE(elev, lc.vmin_deg - 1.0);
    EXPECT_LE(elev, lc.vmax_deg + 1.0);
  }
}

TEST(Uav, FollowsPathWithinLimits) {
  World w = test::boxRoom(8, 6);
  GroundTruthGrid gt(w, 0.05);
  UavConfig uc;
  Uav uav(uc, Pose{Vec3(1, 1, 1.2), 0.0});
  uav.setPath({Vec3(1, 1, 1.2), Vec3(6, 1, 1.2), Vec3(6, 4, 1.2)});
  const double dt = 0.1;
  Vec3 prev = uav.pose().position;
  double prev_speed = 0, prev_yaw = uav.pose().yaw;
  for (int i = 0; i < 400 && !uav.idle(); ++i) {
    ASSERT_TRUE(uav.step(gt, dt));
    const double v = (uav.pose().position - prev).norm() / dt;
    EXPECT_LE(v, uc.max_speed + 1e-9);
    EXPECT_LE(uav.speed() - prev_speed, uc.max_accel * dt + 1e-9);
    EXPECT_LE(std::abs(wrapAngle(uav.pose().yaw - prev_yaw)), deg2rad(uc.max_yaw_rate_deg) * dt + 1e-9);
    prev = uav.pose().position;
    prev_speed = uav.speed();
    prev_yaw = uav.pose().yaw;
  }
  EXPECT_NEAR((uav.pose().position - Vec3(6, 4, 1.2)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(uav.distanceTravelled(), 8.0, 1e-6);
  EXPECT_EQ(uav.collisions(), 0);
}

TEST(Uav, APathRepeatingItsLastPointEnds) {
  // Planned paths can repeat a point (house_1 "toilet": a viewpoint path ending in the same point
  // twice held the UAV there, never done, for 270 s).
  World w = test::boxRoom(8, 6);
  GroundTruthGrid gt(w, 0.05);
  Uav uav(UavConfig{}, Pose{Vec3(1, 1, 1.2), 0.0});
  uav.setPath({Vec3(2, 1, 1.2), Vec3(2, 1.5, 1.25), Vec3(2, 1.5, 1.25), Vec3(2, 1.5, 1.25)});
  int steps = 0;
  while (!uav.pathDone() && steps < 200) {
    ASSERT_TRUE(uav.step(gt, 0.1));
    ++steps;
  }
  EXPECT_TRUE(uav.pathDone());
  EXPECT_LT(steps, 50);
  EXPECT_NEAR((uav.pose().position - Vec3(2, 1.5, 1.25)).norm(), 0.0, 1e-9);
}

TEST(Uav, FlyingIntoAWallIsACollisionAndStopsOutside) {
  World w = test::boxRoom(6, 4);
  GroundTruthGrid gt(w, 0.05);
  UavConfig uc;
  uc.max_speed = 3.0;
  uc.max_accel = 5.0;
  Uav uav(uc, Pose{Vec3(3, 2, 1.2), 0.0});
  uav.setPath({Vec3(8, 2, 1.2)});  // straight through the wall at x = 6
  int failed = 0;
  for (int i = 0; i < 100; ++i) failed += !uav.step(gt, 0.1);
  EXPECT_EQ(uav.collisions(), 1);
  EXPECT_EQ(failed, 1);
  EXPECT_FALSE(gt.sphereCollides(uav.pose().position, uc.radius));
  EXPECT_LT(uav.pose().position.x(), 5.95 - uc.radius + 1e-9);
}
