#include <gtest/gtest.h>

#include <cmath>

#include "ussnav/core/random.hpp"
#include "ussnav/objects/cloud.hpp"

using namespace ussnav;

namespace {
DepthFrame smallFrame() {
  DepthFrame f;
  f.K.width = 4;
  f.K.height = 3;
  f.K.fx = f.K.fy = 2.0;
  f.K.cx = 1.5;
  f.K.cy = 1.0;
  f.depth.assign(12, 2.0f);
  f.max_range = 5.0;
  // UAV at (1, 2, 3) facing +y (yaw 90 degrees), camera level.
  Pose pose{Vec3(1, 2, 3), kPi / 2};
  f.T_world_camera = pose.toIsometry();
  f.T_world_camera.linear() = pose.toIsometry().linear() * opticalToBody();
  return f;
}
}  // namespace

TEST(BackProject, KnownPixelLandsAtKnownWorldPoint) {
  const DepthFrame f = smallFrame();
  // Pixel (u=3, v=0) at depth 2: camera (1.5, -1, 2) -> body (2, -1.5, 1) -> yaw 90 (1.5, 2, 1)
  // -> world (2.5, 4, 4).
  const auto p = backProject(f, {3});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].x(), 2.5, 1e-5);
  EXPECT_NEAR(p[0].y(), 4.0, 1e-5);
  EXPECT_NEAR(p[0].z(), 4.0, 1e-5);
  // The principal point looks straight ahead (+y in the world), at the camera's height.
  DepthFrame g = f;
  g.K.cx = 1.0;
  const auto q = backProject(g, {1 * 4 + 1});
  ASSERT_EQ(q.size(), 1u);
  EXPECT_NEAR((q[0].cast<double>() - Vec3(1, 4, 3)).norm(), 0.0, 1e-5);
}

TEST(BackProject, SkipsInvalidDepthAndIndices) {
  DepthFrame f = smallFrame();
  f.depth[0] = 0.0f;
  f.depth[1] = std::nanf("");
  f.depth[2] = 7.0f;  // beyond max_range
  f.depth[3] = 4.9f;
  const auto p = backProject(f, {0, 1, 2, 3, 99});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR((p[0].cast<double>() - f.T_world_camera.translation()).norm(),
              4.9 * std::sqrt(1 + 0.75 * 0.75 + 0.5 * 0.5), 1e-4);
}

TEST(VoxelDownsample, OnePointPerVoxelAtTheMean) {
  const std::vector<Vec3f> pts{{0.01f, 0.01f, 0.01f}, {0.03f, 0.03f, 0.03f}, {0.07f, 0.0f, 0.0f},
                               {-0.01f, 0.0f, 0.0f}};
  const auto d = voxelDownsample(pts, 0.05);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR((d[0] - Vec3f(0.02f, 0.02f, 0.02f)).norm(), 0.0, 1e-6);  // first voxel hit first
  EXPECT_NEAR(d[1].x(), 0.07f, 1e-6);
  EXPECT_NEAR(d[2].x(), -0.01f, 1e-6);  // floor, not truncation: a different voxel from 0.01
}

TEST(GeometricOverlap, MatchesBruteForce) {
  Rng rng(3);
  std::vector<Vec3f> a, b;
  for (int i = 0; i < 400; ++i) a.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.2, 0.2));
  for (int i = 0; i < 300; ++i) b.emplace_back(rng.uniform(-0.5, 1.5), rng.uniform(-1, 1), rng.uniform(-0.2, 0.2));
  for (double tau : {0.05, 0.1, 0.3}) {
    int hit = 0;
    for (const auto& p : a) {
      bool any = false;
      for (const auto& q : b) any = any || (p - q).norm() <= tau;
      hit += any;
    }
    EXPECT_DOUBLE_EQ(geometricOverlap(a, b, tau), double(hit) / a.size()) << tau;
  }
}

TEST(GeometricOverlap, DirectionalAndThresholdedByTau) {
  std::vector<Vec3f> line, half;
  for (int i = 0; i < 100; ++i) line.emplace_back(0.02f * i, 0, 0);
  for (int i = 0; i < 50; ++i) half.emplace_back(0.02f * i, 0, 0);
  EXPECT_DOUBLE_EQ(geometricOverlap(half, line, 0.01), 1.0);
  EXPECT_DOUBLE_EQ(geometricOverlap(line, half, 0.01), 0.5);
  std::vector<Vec3f> shifted;
  for (const auto& p : line) shifted.push_back(p + Vec3f(0, 0.15f, 0));
  EXPECT_DOUBLE_EQ(geometricOverlap(line, shifted, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(geometricOverlap(line, shifted, 0.16), 1.0);
  EXPECT_DOUBLE_EQ(geometricOverlap({}, line, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(geometricOverlap(line, {}, 0.1), 0.0);
}

TEST(VoxelCloud, MeansPerVoxelAndExactNeighbourQueries) {
  Rng rng(11);
  VoxelCloud vc(0.05, 0.1);
  std::vector<Vec3f> raw;
  for (int round = 0; round < 3; ++round) {  // grows by insertion; means move inside voxels
    std::vector<Vec3f> batch;
    for (int i = 0; i < 500; ++i) batch.emplace_back(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(0, 0.3));
    vc.insert(batch);
    raw.insert(raw.end(), batch.begin(), batch.end());
  }
  const auto expected = voxelDownsample(raw, 0.05);
  ASSERT_EQ(vc.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR((vc.points()[i] - expected[i]).norm(), 0.0, 1e-5);
  // Against brute force over the means, including queries far outside.
  for (int q = 0; q < 2000; ++q) {
    const Vec3f p(rng.uniform(-0.8, 0.8), rng.uniform(-0.8, 0.8), rng.uniform(-0.3, 0.6));
    bool any = false;
    for (const auto& m : vc.points()) any = any || (m - p).norm() <= 0.1f;
    ASSERT_EQ(vc.hasNeighbor(p), any) << p.transpose();
  }
}

TEST(VoxelCloud, CoarsenHalvesResolutionAndKeepsQueriesExact) {
  Rng rng(12);
  VoxelCloud vc(0.05, 0.1);
  std::vector<Vec3f> raw;
  for (int i = 0; i < 3000; ++i) raw.emplace_back(rng.uniform(0, 1), rng.uniform(0, 1), 0.0f);
  vc.insert(raw);
  const size_t before = vc.size();
  vc.coarsen();
  EXPECT_DOUBLE_EQ(vc.voxelSize(), 0.1);
  EXPECT_LT(vc.size(), before / 3);
  EXPECT_EQ(vc.size(), voxelDownsample(raw, 0.1).size());
  for (int q = 0; q < 500; ++q) {
    const Vec3f p(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.15, 0.15));
    bool any = false;
    for (const auto& m : vc.points()) any = any || (m - p).norm() <= 0.1f;
    ASSERT_EQ(vc.hasNeighbor(p), any);
  }
}

TEST(VoxelCloud, OverlapIsExactAboveTheNeed) {
  std::vector<Vec3f> line;
  for (int i = 0; i < 100; ++i) line.emplace_back(0.04f * i + 0.001f, 0, 0);
  VoxelCloud firstThird(0.02, 0.1);  // one point per voxel: the means are the points
  firstThird.insert(std::vector<Vec3f>(line.begin(), line.begin() + 30));
  const double exact = geometricOverlap(line, firstThird);
  EXPECT_NEAR(exact, 32.0 / 100.0, 1e-9);  // 30 points plus two within tau (0.04, 0.08) of the last
  EXPECT_DOUBLE_EQ(geometricOverlap(line, firstThird, 0.1), exact);  // above the need: exact
  EXPECT_LE(geometricOverlap(line, firstThird, 0.5), 0.5);             // below: cut short
}
