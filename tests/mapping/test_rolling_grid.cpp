#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>

#include "support/mapping_scenes.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

using namespace ussnav;
using test::BoxScene;

namespace {

// Interior 6.06 x 5.78 x 2.73 m: fits in the default 8 x 8 x 4 window around (0, 0, 1.2).
BoxScene room() { return test::boxRoom(Vec3(-3.03, -2.87, 0.0), Vec3(3.03, 2.91, 2.73)); }

Intrinsics d455(int w, int h) { return Intrinsics::fromFov(w, h, deg2rad(87), deg2rad(58)); }

struct Truth {
  int occupied = 0, occupied_near_surface = 0, free = 0, free_in_truth = 0;
};

// Judges every voxel of the window against the analytic scene.
Truth judge(const RollingGrid& g, const BoxScene& scene, const char* what) {
  Truth t;
  const double r = g.resolution();
  const Vec3i lo = g.minKey(), hi = g.minKey() + g.dims();
  for (int z = lo.z(); z < hi.z(); ++z)
    for (int y = lo.y(); y < hi.y(); ++y)
      for (int x = lo.x(); x < hi.x(); ++x) {
        const Vec3i k(x, y, z);
        const VoxelState s = g.stateFast(k);
        if (s == VoxelState::Occupied) {
          ++t.occupied;
          t.occupied_near_surface += scene.voxelNearSurface(k, r, r);
        } else if (s == VoxelState::Free) {
          ++t.free;
          t.free_in_truth += scene.voxelFreeInTruth(k, r);
        }
      }
  std::printf("[ %s ] occupied %d (%d near a surface), free %d (%.3f%% free in truth)\n", what, t.occupied,
              t.occupied_near_surface, t.free, 100.0 * t.free_in_truth / std::max(1, t.free));
  return t;
}

// Keeps a shadow copy of the grid from its change log only.
struct Shadow {
  std::unordered_map<uint64_t, VoxelState> known;
  static uint64_t pack(const Vec3i& k) {
    return uint64_t(uint32_t(k.x()) & 0x1FFFFF) << 42 | uint64_t(uint32_t(k.y()) & 0x1FFFFF) << 21 |
           uint64_t(uint32_t(k.z()) & 0x1FFFFF);
  }
  VoxelState get(const Vec3i& k) const {
    const auto it = known.find(pack(k));
    return it == known.end() ? VoxelState::Unknown : it->second;
  }
  // Applies and clears the log; returns false if an entry's `before` disagrees.
  bool consume(RollingGrid& g) {
    bool ok = true;
    for (const VoxelChange& c : g.changes()) {
      ok &= get(c.key) == c.before;
      if (c.after == VoxelState::Unknown) known.erase(pack(c.key));
      else known[pack(c.key)] = c.after;
    }
    g.clearChanges();
    return ok;
  }
};

}  // namespace

TEST(MappingScenes, DepthIsExactZDepth) {
  const BoxScene scene = room();
  // Looking along +x from x = 0: the east wall's inner face is 3.03 m away at every pixel row
  // through the centre, and z-depth stays 3.03 off-axis too (a plane facing the camera).
  const DepthFrame f = test::renderDepth(scene, d455(64, 48), test::cameraPose(Vec3(0, 0, 1.5), 0.0), 5.0);
  EXPECT_NEAR(f.depth[24 * 64 + 32], 3.03, 1e-5);
  EXPECT_NEAR(f.depth[24 * 64 + 40], 3.03, 1e-5);
  EXPECT_TRUE(scene.voxelFreeInTruth(Vec3i(0, 0, 10), 0.1));
  EXPECT_FALSE(scene.voxelFreeInTruth(Vec3i(30, 0, 10), 0.1));  // [3.0, 3.1] holds the face 3.03
  EXPECT_TRUE(scene.voxelNearSurface(Vec3i(30, 0, 10), 0.1, 0.1));
  EXPECT_FALSE(scene.voxelNearSurface(Vec3i(10, 0, 10), 0.1, 0.1));
}

TEST(RollingGrid, ConfigValidation) {
  GridConfig c;
  EXPECT_EQ(RollingGrid(c).dims(), Vec3i(80, 80, 40));
  c.size_x = 0;
  try {
    RollingGrid g(c);
    FAIL() << "zero size accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("size_x"), std::string::npos) << e.what();
  }
  c = GridConfig{};
  c.resolution = 0;
  EXPECT_THROW(RollingGrid{c}, InputError);
  c = GridConfig{};
  c.size_z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RollingGrid{c}, InputError);
  c = GridConfig{};
  c.occupied_threshold = 4.0;  // above log_odds_max: nothing could ever be occupied
  EXPECT_THROW(RollingGrid{c}, InputError);
  c = GridConfig{};
  c.resolution = 0.001;  // 8000^2 * 4000 voxels
  EXPECT_THROW(RollingGrid{c}, InputError);
}

TEST(RollingGrid, MemoryIsFixedByTheConfig) {
  GridConfig c;
  RollingGrid g(c, Vec3(0, 0, 1.2));
  EXPECT_EQ(RollingGrid::voxelBytes(c), size_t(80 * 80 * 40) * 4);
  EXPECT_GE(g.memoryBytes(), RollingGrid::voxelBytes(c));
  EXPECT_LT(g.memoryBytes(), RollingGrid::voxelBytes(c) + 4096);
  const Aabb w = g.window();
  EXPECT_NEAR(w.size().x(), 8.0, 1e-9);
  EXPECT_NEAR(w.size().z(), 4.0, 1e-9);
  EXPECT_TRUE(w.contains(Vec3(0, 0, 1.2)));
}

TEST(RollingGrid, DepthFramesAgreeWithGroundTruth) {
  const BoxScene scene = room();
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  int rays = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p(0.3 * std::cos(i), -0.4 + 0.1 * i, 1.1 + 0.05 * i);
    const DepthFrame f = test::renderDepth(scene, d455(320, 240), test::cameraPose(p, i * kPi / 4, 0.2), 5.0);
    const InsertStats st = g.insertDepth(f);
    EXPECT_FALSE(st.rejected);
    EXPECT_EQ(st.invalid, 0);
    EXPECT_EQ(st.hits + st.hits_outside + st.no_return, 320 * 240);
    rays += st.rays;
  }
  EXPECT_GT(rays, 8 * 1000);
  const Truth t = judge(g, scene, ::testing::UnitTest::GetInstance()->current_test_info()->name());
  EXPECT_GT(t.occupied, 5000);
  EXPECT_GT(t.free, 50000);
  EXPECT_EQ(t.occupied_near_surface, t.occupied) << "occupied voxels away from any true surface";
  EXPECT_GE(double(t.free_in_truth), 0.99 * t.free) << t.free_in_truth << " of " << t.free;
  EXPECT_EQ(g.knownVoxels(), size_t(t.occupied + t.free));
}

TEST(RollingGrid, NoisyDepthStaysWithinOneVoxel) {
  const BoxScene scene = room();
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  for (int i = 0; i < 4; ++i)
    g.insertDepth(test::renderDepth(scene, d455(160, 120), test::cameraPose(Vec3(0, 0, 1.2), i * kPi / 2), 5.0,
                                    0.01, 7 + i));
  const Truth t = judge(g, scene, ::testing::UnitTest::GetInstance()->current_test_info()->name());
  EXPECT_GT(t.occupied, 1000);
  EXPECT_EQ(t.occupied_near_surface, t.occupied);
  EXPECT_GE(double(t.free_in_truth), 0.99 * t.free) << t.free_in_truth << " of " << t.free;
}

TEST(RollingGrid, LidarScansAgreeWithGroundTruth) {
  const BoxScene scene = room();
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  for (int i = 0; i < 4; ++i) {
    const Vec3 o(-0.5 + 0.4 * i, 0.3 - 0.2 * i, 1.2);
    const PointCloudScan s = test::renderScan(scene, o, 20000, -7, 52, 40.0, 0.1 * i);
    ASSERT_EQ(s.points.size(), 20000u);  // closed room: every ray returns
    const InsertStats st = g.insertScan(s);
    EXPECT_EQ(st.hits, 20000);
    EXPECT_EQ(st.invalid, 0);
  }
  const Truth t = judge(g, scene, ::testing::UnitTest::GetInstance()->current_test_info()->name());
  EXPECT_GT(t.occupied, 3000);
  EXPECT_GT(t.free, 30000);
  EXPECT_EQ(t.occupied_near_surface, t.occupied);
  EXPECT_GE(double(t.free_in_truth), 0.99 * t.free) << t.free_in_truth << " of " << t.free;
}

// The simulator's ground truth puts walls on a 0.05 m lattice, so half of all wall faces lie on
// a voxel face. A return there must count in the voxel behind the face: counted in the free voxel
// in front (rounding decides, ray by ray), it is cleared again by the rays that graze the wall
// on their way to its other points, and a wall seen from one side only stays a gap (house_18:
// the fridge "seen" from the bathroom through the unmapped wall behind it).
TEST(RollingGrid, ReturnsOnAVoxelFaceMarkTheVoxelBehindIt) {
  const BoxScene scene = test::boxRoom(Vec3(-3.0, -2.8, 0.0), Vec3(3.0, 2.8, 2.7), 0.2, false);
  for (const double side : {1.0, -1.0}) {  // rounding puts returns on one side of a face or the other
    RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
    for (int i = 0; i < 6; ++i)  // a flight along the room, 0.4 m from one long wall
      g.insertScan(test::renderScan(scene, Vec3(-2.0 + 0.8 * i, side * 2.4, 1.2), 20000, -7, 52, 40.0, 0.3 * i));
    int behind = 0, behind_occupied = 0, front_free = 0;
    for (double x = -1.95; x < 2.0; x += 0.1)
      for (double z = 1.25; z < 1.9; z += 0.1) {  // the near wall above the UAV: grazing rays
        ++behind;
        behind_occupied += g.stateAt(Vec3(x, side * 2.85, z)) == VoxelState::Occupied;
        front_free += g.stateAt(Vec3(x, side * 2.75, z)) == VoxelState::Free;
      }
    EXPECT_EQ(behind_occupied, behind) << (side > 0 ? "+y" : "-y") << " wall: voxels behind the face not occupied";
    EXPECT_EQ(front_free, behind) << (side > 0 ? "+y" : "-y") << " wall: voxels in front of the face not free";
  }
}

TEST(RollingGrid, HitWinsOverMissInOneFrameAndLogOddsClamp) {
  RollingGrid g(GridConfig{}, Vec3(0, 0, 0));
  PointCloudScan s;
  s.origin = Vec3(0.05, 0.05, 0.05);
  s.points = {Vec3f(1.05f, 0.05f, 0.05f), Vec3f(2.05f, 0.05f, 0.05f)};  // the first lies on the second's ray
  g.insertScan(s);
  EXPECT_EQ(g.stateAt(Vec3(1.05, 0.05, 0.05)), VoxelState::Occupied);
  EXPECT_EQ(g.stateAt(Vec3(2.05, 0.05, 0.05)), VoxelState::Occupied);
  EXPECT_EQ(g.stateAt(Vec3(1.55, 0.05, 0.05)), VoxelState::Free);
  EXPECT_EQ(g.stateAt(Vec3(0.05, 0.05, 0.05)), VoxelState::Free);  // the sensor's own voxel
  EXPECT_EQ(g.stateAt(Vec3(2.55, 0.05, 0.05)), VoxelState::Unknown);
  EXPECT_NEAR(g.logOdds(g.keyOf(Vec3(1.05, 0.05, 0.05))), 0.85f, 1e-3);
  for (int i = 0; i < 20; ++i) g.insertScan(s);
  EXPECT_NEAR(g.logOdds(g.keyOf(Vec3(2.05, 0.05, 0.05))), 3.5f, 1e-3);
  EXPECT_NEAR(g.logOdds(g.keyOf(Vec3(0.55, 0.05, 0.05))), -2.0f, 1e-3);
  // Two misses take a once-hit voxel (0.85) to 0.05, still occupied; a third frees it.
  RollingGrid h(GridConfig{}, Vec3(0, 0, 0));
  PointCloudScan hit = s, pass = s;
  hit.points = {Vec3f(1.05f, 0.05f, 0.05f)};
  pass.points = {Vec3f(1.95f, 0.05f, 0.05f)};
  h.insertScan(hit);
  h.insertScan(pass);
  h.insertScan(pass);
  EXPECT_EQ(h.stateAt(Vec3(1.05, 0.05, 0.05)), VoxelState::Occupied);
  h.insertScan(pass);
  EXPECT_EQ(h.stateAt(Vec3(1.05, 0.05, 0.05)), VoxelState::Free);
}

TEST(RollingGrid, NoReturnCarvesToMaxRangeAndStopsAtWindow) {
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  PointCloudScan s;
  s.origin = Vec3(0.05, 0.05, 1.25);
  s.max_range = 2.0;
  s.no_return_dirs = {Vec3f(1, 0, 0), Vec3f(0, -3, 0)};  // not unit: normalised
  s.points = {Vec3f(0.05f, 30.05f, 1.25f)};              // far beyond the window
  const InsertStats st = g.insertScan(s);
  EXPECT_EQ(st.no_return, 2);
  EXPECT_EQ(st.hits_outside, 1);
  EXPECT_EQ(g.stateAt(Vec3(1.95, 0.05, 1.25)), VoxelState::Free);
  EXPECT_EQ(g.stateAt(Vec3(2.15, 0.05, 1.25)), VoxelState::Unknown);
  EXPECT_EQ(g.stateAt(Vec3(0.05, -1.95, 1.25)), VoxelState::Free);
  EXPECT_EQ(g.stateAt(Vec3(0.05, 3.95, 1.25)), VoxelState::Free);  // last voxel of the window
  for (const VoxelChange& c : g.changes()) EXPECT_TRUE(g.inWindow(c.key));
  EXPECT_EQ(g.knownVoxels(), g.changes().size());
}

TEST(RollingGrid, RollingKeepsWorldLookupsConsistent) {
  const BoxScene scene = room();
  const Vec3 p0(0.2, -0.1, 1.2);
  RollingGrid g(GridConfig{}, p0);
  g.insertScan(test::renderScan(scene, p0, 20000, -7, 52, 40.0));
  std::vector<std::pair<Vec3i, VoxelState>> before;
  for (int z = g.minKey().z(); z < g.minKey().z() + g.dims().z(); ++z)
    for (int y = g.minKey().y(); y < g.minKey().y() + g.dims().y(); ++y)
      for (int x = g.minKey().x(); x < g.minKey().x() + g.dims().x(); ++x)
        before.push_back({Vec3i(x, y, z), g.stateFast(Vec3i(x, y, z))});
  const Vec3i w0 = g.minKey();
  const auto inW0 = [&](const Vec3i& k) {
    return ((k - w0).array() >= 0).all() && ((k - w0 - g.dims()).array() < 0).all();
  };
  g.moveTo(p0 + Vec3(1.04, -0.53, 0.31));
  const Vec3i w1 = g.minKey();
  EXPECT_NE(w1, w0);
  int kept = 0, known_kept = 0;
  for (const auto& [k, s] : before) {
    if (g.inWindow(k)) {
      ASSERT_EQ(g.state(k), s) << k.transpose();
      ++kept;
      known_kept += s != VoxelState::Unknown;
    } else {
      ASSERT_EQ(g.state(k), VoxelState::Unknown);
    }
  }
  EXPECT_EQ(g.knownVoxels(), size_t(known_kept));
  EXPECT_GT(kept, int(before.size()) / 2);
  // Back again: what stayed inside both windows is unchanged, what left and re-entered is reset.
  g.moveTo(p0);
  EXPECT_EQ(g.minKey(), w0);
  for (const auto& [k, s] : before) {
    const bool stayed = ((k - w1).array() >= 0).all() && ((k - w1 - g.dims()).array() < 0).all();
    ASSERT_TRUE(inW0(k));
    ASSERT_EQ(g.state(k), stayed ? s : VoxelState::Unknown) << k.transpose();
  }
}

TEST(RollingGrid, RingOffsetDoesNotChangeTheMap) {
  // The same frames give the same map whatever ring offset earlier rolls left behind.
  const BoxScene scene = room();
  const Vec3 p0(0.2, -0.1, 1.2);
  RollingGrid a(GridConfig{}, p0), b(GridConfig{}, p0);
  for (const Vec3& d : {Vec3(2.37, 0, 0), Vec3(-1.1, 3.3, -0.7), Vec3(500, -200, 10), Vec3(0.35, 0.45, 0.15)})
    b.moveTo(p0 + d);
  b.moveTo(p0);
  EXPECT_EQ(b.knownVoxels(), 0u);
  for (RollingGrid* g : {&a, &b}) {
    g->insertScan(test::renderScan(scene, p0, 5000, -7, 52, 40.0));
    g->insertDepth(test::renderDepth(scene, d455(160, 120), test::cameraPose(p0, 0.7), 5.0));
  }
  ASSERT_EQ(a.minKey(), b.minKey());
  ASSERT_GT(a.knownVoxels(), 1000u);
  EXPECT_EQ(a.knownVoxels(), b.knownVoxels());
  for (int z = a.minKey().z(); z < a.minKey().z() + a.dims().z(); ++z)
    for (int y = a.minKey().y(); y < a.minKey().y() + a.dims().y(); ++y)
      for (int x = a.minKey().x(); x < a.minKey().x() + a.dims().x(); ++x) {
        const Vec3i k(x, y, z);
        ASSERT_EQ(a.stateFast(k), b.stateFast(k)) << k.transpose();
        ASSERT_EQ(a.logOdds(k), b.logOdds(k)) << k.transpose();
      }
}

TEST(RollingGrid, ChangeLogReproducesTheGridThroughRandomRolls) {
  const BoxScene scene = test::boxRoom(Vec3(-8, -6, 0), Vec3(8, 6, 2.9));
  Rng rng(42);
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  Shadow shadow;
  for (int step = 0; step < 25; ++step) {
    const Vec3 p(rng.uniform(-6, 6), rng.uniform(-4.5, 4.5), rng.uniform(0.8, 1.8));
    g.moveTo(p + Vec3(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.3, 0.3)));
    if (step % 2) g.insertScan(test::renderScan(scene, p, 3000, -7, 52, 40.0, rng.uniform(0, 6)));
    else g.insertDepth(test::renderDepth(scene, d455(80, 60), test::cameraPose(p, rng.uniform(-3, 3)), 5.0));
    ASSERT_TRUE(shadow.consume(g)) << "change log out of order at step " << step;
    ASSERT_EQ(shadow.known.size(), g.knownVoxels());
    for (int z = g.minKey().z(); z < g.minKey().z() + g.dims().z(); ++z)
      for (int y = g.minKey().y(); y < g.minKey().y() + g.dims().y(); ++y)
        for (int x = g.minKey().x(); x < g.minKey().x() + g.dims().x(); ++x)
          ASSERT_EQ(shadow.get(Vec3i(x, y, z)), g.stateFast(Vec3i(x, y, z)));
  }
  EXPECT_GT(g.counters().rolls, 20u);
  EXPECT_GT(g.counters().voxels_rolled_out, 10000u);
}

TEST(RollingGrid, MemoryDoesNotGrowOverALongFlight) {
  // 200 m of corridor. The voxel arrays are fixed; scratch buffers (rays, change log) reach
  // the size the largest frame needs and then stay: no growth with distance flown.
  const BoxScene scene = test::corridor(200, 3.0, 2.8);
  RollingGrid g(GridConfig{}, Vec3(1, 0, 1.2));
  size_t settled = 0;
  for (double x = 1.0; x < 199.0; x += 1.0) {
    const Vec3 p(x, 0.2 * std::sin(x), 1.2);
    g.moveTo(p);
    g.insertScan(test::renderScan(scene, p, 3000, -7, 52, 40.0, x));
    g.clearChanges();
    if (x == 50.0) settled = g.memoryBytes();
    if (x > 50.0) {
      ASSERT_EQ(g.memoryBytes(), settled) << "memory grew at x = " << x;
    }
    ASSERT_LE(g.knownVoxels(), g.voxelCount());
  }
  EXPECT_LT(g.memoryBytes(), RollingGrid::voxelBytes(GridConfig{}) + (1 << 20));
  EXPECT_GT(g.counters().rolls, 190u);
  EXPECT_EQ(g.counters().rejected_frames, 0u);
  // The map still describes the corridor around the UAV at the end.
  EXPECT_EQ(g.stateAt(Vec3(198.5, 1.55, 1.2)), VoxelState::Occupied);
  EXPECT_EQ(g.stateAt(Vec3(198.5, 0.0, 1.2)), VoxelState::Free);
  EXPECT_EQ(g.stateAt(Vec3(1.0, 0.0, 1.2)), VoxelState::Unknown);  // long gone
}

TEST(RollingGrid, QueriesOnAMappedRoom) {
  const BoxScene scene = room();
  const Vec3 c(0, 0, 1.2);
  RollingGrid g(GridConfig{}, c);
  g.insertScan(test::renderScan(scene, c, 20000, -7, 52, 40.0));
  for (int i = 0; i < 4; ++i) g.insertDepth(test::renderDepth(scene, d455(160, 120), test::cameraPose(c, i * kPi / 2), 5.0));
  EXPECT_TRUE(g.lineOfSight(c, Vec3(2.5, 0.2, 1.0), true));
  EXPECT_FALSE(g.lineOfSight(c, Vec3(3.5, 0.2, 1.0), false));  // through the east wall
  const RayHit h = g.castRay(c, Vec3(3.8, 0, 1.2), false);
  EXPECT_TRUE(h.blocked);
  EXPECT_NEAR(h.point.x(), 3.0, 1e-9);  // entry of voxel [3.0, 3.1), which holds the face 3.03
  const RayHit generic = castRay(static_cast<const OccupancyMap&>(g), c, Vec3(3.8, 0, 1.2), false);
  EXPECT_EQ(generic.point, h.point);
  // East wall face at x = 3.03 lies in voxels [3.0, 3.1]; from x = 2.53 that box is 0.47 away.
  const Vec3 p(2.53, 0.05, 1.25);
  const double d = g.distanceToObstacle(p, 2.0);
  EXPECT_NEAR(d, 0.47, 1e-6);
  EXPECT_DOUBLE_EQ(g.distanceToObstacle(Vec3(0, 0, 1.2), 0.3), 0.3);  // nothing within 0.3 m
  EXPECT_TRUE(g.isInflatedOccupied(p, 0.6));
  EXPECT_FALSE(g.isInflatedOccupied(p, 0.3));
  EXPECT_EQ(g.isInflatedOccupied(p, 0.3), !isSafe(g, p, 0.3, false));
  EXPECT_TRUE(g.isInflatedOccupied(Vec3(3.9, 3.9, 1.2), 0.05, true));  // unknown behind the wall
}

TEST(RollingGrid, BadInputsAreErrorsOrCountedSkips) {
  const BoxScene scene = room();
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  DepthFrame f = test::renderDepth(scene, d455(32, 24), test::cameraPose(Vec3(0, 0, 1.2), 0), 5.0);
  // NaN and negative pixels are skipped and counted, never carved.
  DepthFrame bad = f;
  for (float& d : bad.depth) d = std::numeric_limits<float>::quiet_NaN();
  bad.depth[0] = -1.f;
  bad.depth[1] = -std::numeric_limits<float>::infinity();
  InsertStats st = g.insertDepth(bad);
  EXPECT_EQ(st.invalid, 32 * 24);
  EXPECT_EQ(g.knownVoxels(), 0u);
  EXPECT_EQ(g.counters().invalid_points, uint64_t(32 * 24));
  // 0 and +inf mean no return: free up to max_range.
  DepthFrame none = f;
  for (float& d : none.depth) d = 0.f;
  none.depth[5] = std::numeric_limits<float>::infinity();
  st = g.insertDepth(none);
  EXPECT_EQ(st.no_return, 32 * 24);
  EXPECT_GT(g.knownVoxels(), 0u);
  EXPECT_EQ(g.stateAt(Vec3(2.0, 0, 1.2)), VoxelState::Free);
  // Malformed frames are InputErrors naming the field.
  DepthFrame nanpose = f;
  nanpose.T_world_camera.translation().x() = std::numeric_limits<double>::quiet_NaN();
  try {
    g.insertDepth(nanpose);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "T_world_camera");
  }
  DepthFrame short_frame = f;
  short_frame.depth.pop_back();
  EXPECT_THROW(g.insertDepth(short_frame), InputError);
  DepthFrame zero_k = f;
  zero_k.K.fx = 0;
  EXPECT_THROW(g.insertDepth(zero_k), InputError);
  // A pose far outside the window: the frame is rejected and counted, the map untouched.
  const size_t known = g.knownVoxels();
  DepthFrame far = f;
  far.T_world_camera.translation() = Vec3(1000, 0, 1.2);
  st = g.insertDepth(far);
  EXPECT_TRUE(st.rejected);
  EXPECT_EQ(g.counters().rejected_frames, 1u);
  EXPECT_EQ(g.knownVoxels(), known);
  // Window moves: non-finite or absurd centres are errors, the window stays put.
  const Vec3i k0 = g.minKey();
  EXPECT_THROW(g.moveTo(Vec3(std::nan(""), 0, 0)), InputError);
  EXPECT_THROW(g.moveTo(Vec3(1e9, 0, 0)), InputError);
  EXPECT_EQ(g.minKey(), k0);
  // Scans: non-finite points and zero directions are skipped and counted.
  PointCloudScan s;
  s.origin = Vec3(0, 0, 1.2);
  s.points = {Vec3f(1, 0, 1.2f), Vec3f(NAN, 0, 0), Vec3f(0, INFINITY, 0)};
  s.no_return_dirs = {Vec3f::Zero(), Vec3f(NAN, 1, 0)};
  st = g.insertScan(s);
  EXPECT_EQ(st.invalid, 4);
  EXPECT_EQ(st.hits, 1);
  s.origin.z() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(g.insertScan(s), InputError);
}
