// castRay on hand-made grids: a segment through a voxel edge or corner is judged the same from
// every start point on it, and never slips between two blocking voxels that touch only there.

#include <gtest/gtest.h>

#include "support/dense_grid.hpp"
#include "ussnav/mapping/occupancy.hpp"

using namespace ussnav;

namespace {

constexpr double kRes = 0.1;

test::DenseGrid freeGrid() { return test::DenseGrid(Aabb(Vec3(0, 0, 0), Vec3(2, 2, 1)), kRes, VoxelState::Free); }

}  // namespace

TEST(CastRay, ThroughAnEdgeBetweenDiagonalBlockersIsBlockedFromAnyStart) {
  // Voxel centres (0.55, 0.55) -> (0.45, 0.05) at z = 0.45: slope 1:5, the line passes exactly
  // through the voxel edge at (0.50, 0.30). The two voxels that meet there diagonally, (4, 3)
  // and (5, 2) in x-y, block; their other diagonal pair, (4, 2) and (5, 3), is free.
  test::DenseGrid grid = freeGrid();
  grid.set(Vec3i(4, 3, 4), VoxelState::Occupied);
  grid.set(Vec3i(5, 2, 4), VoxelState::Occupied);
  const Vec3 a(0.55, 0.55, 0.45), b(0.45, 0.05, 0.45);
  for (const double s : {0.0, 0.1, 0.2, 0.3, 0.4}) {  // start points along the line, up to the edge
    const Vec3 from = a + (b - a) * s;
    const RayHit h = castRay(grid, from, b, false);
    EXPECT_TRUE(h.blocked) << "from " << from.transpose();
    EXPECT_NEAR(h.point.y(), 0.30, 1e-9);
    EXPECT_TRUE(castRay(grid, b, from, false).blocked) << "to " << from.transpose();  // either way
  }
  // One blocker is enough (whichever the walk would have stepped into first).
  for (const Vec3i& k : {Vec3i(4, 3, 4), Vec3i(5, 2, 4)}) {
    test::DenseGrid one = freeGrid();
    one.set(k, VoxelState::Occupied);
    EXPECT_TRUE(castRay(one, a, b, false).blocked) << k.transpose();
    EXPECT_TRUE(castRay(one, a + (b - a) * 0.2, b, false).blocked) << k.transpose();
  }
  // Unknown side voxels block only when asked to.
  test::DenseGrid unknown = freeGrid();
  unknown.set(Vec3i(4, 3, 4), VoxelState::Unknown);
  EXPECT_FALSE(castRay(unknown, a, b, false).blocked);
  EXPECT_EQ(castRay(unknown, a, b, true).hit_state, VoxelState::Unknown);
}

TEST(CastRay, OffTheEdgeOnlyTheVoxelsCrossedCount) {
  // The same blockers, the segment shifted 1 cm in x: it crosses (5, 3) then (5, 2) and meets
  // (5, 2); shifted the other way it never enters (5, 2) and passes (4, 3) instead.
  test::DenseGrid grid = freeGrid();
  grid.set(Vec3i(5, 2, 4), VoxelState::Occupied);
  EXPECT_TRUE(castRay(grid, Vec3(0.56, 0.55, 0.45), Vec3(0.46, 0.05, 0.45), false).blocked);
  EXPECT_FALSE(castRay(grid, Vec3(0.54, 0.55, 0.45), Vec3(0.44, 0.05, 0.45), false).blocked);
  // A segment along a voxel boundary plane tests what it walks through, as before: the free row.
  test::DenseGrid row = freeGrid();
  row.fill(Aabb(Vec3(0, 0.9, 0), Vec3(2, 1.0, 1)), VoxelState::Occupied);
  EXPECT_FALSE(castRay(row, Vec3(0.15, 0.75, 0.45), Vec3(1.85, 0.75, 0.45), false).blocked);
  EXPECT_TRUE(castRay(row, Vec3(0.15, 0.75, 0.45), Vec3(0.15, 1.25, 0.45), false).blocked);
}
