// InflatedMap: obstacles grown by a radius, over Free and Unknown voxels alike.

#include <gtest/gtest.h>

#include "ussnav/mapping/inflated_map.hpp"

using namespace ussnav;

TEST(InflatedMap, GrowsObstaclesOverFreeAndUnseenVoxels) {
  // One return at x = 1.05 from a sensor at the origin: that voxel Occupied, the voxels on the
  // ray Free, all else Unknown. A voxel within the radius of the return is Occupied whether the
  // sensor saw it or not (a path through unseen space keeps its margin from a seen wall, the
  // door jamb of FlightPath.RouteComingBackIntoTheWindowPassesADoor); farther, the base state.
  RollingGrid g(GridConfig{}, Vec3(0, 0, 0));
  PointCloudScan s;
  s.origin = Vec3(0.05, 0.05, 0.05);
  s.points = {Vec3f(1.05f, 0.05f, 0.05f)};
  g.insertScan(s);
  ASSERT_EQ(g.stateAt(Vec3(1.05, 0.05, 0.05)), VoxelState::Occupied);
  ASSERT_EQ(g.stateAt(Vec3(0.85, 0.05, 0.05)), VoxelState::Free);
  ASSERT_EQ(g.stateAt(Vec3(1.05, 0.25, 0.05)), VoxelState::Unknown);

  const InflatedMap m(g, 0.25);
  EXPECT_EQ(m.stateAt(Vec3(1.05, 0.05, 0.05)), VoxelState::Occupied);
  EXPECT_EQ(m.stateAt(Vec3(0.85, 0.05, 0.05)), VoxelState::Occupied);   // seen free, 0.2 m away
  EXPECT_EQ(m.stateAt(Vec3(1.05, 0.25, 0.05)), VoxelState::Occupied);   // unseen, 0.2 m away
  EXPECT_EQ(m.stateAt(Vec3(1.25, 0.15, 0.05)), VoxelState::Occupied);   // unseen, 0.22 m away
  EXPECT_EQ(m.stateAt(Vec3(0.55, 0.05, 0.05)), VoxelState::Free);       // seen free, 0.5 m away
  EXPECT_EQ(m.stateAt(Vec3(1.05, 0.45, 0.05)), VoxelState::Unknown);    // unseen, 0.4 m away
  EXPECT_EQ(m.stateAt(Vec3(1.35, 0.25, 0.05)), VoxelState::Unknown);    // unseen, 0.36 m away
  // A flight band: voxels with centres outside it are Occupied.
  const InflatedMap band(g, 0.25, 0.0, 0.5);
  EXPECT_EQ(band.stateAt(Vec3(0.55, 0.05, 0.05)), VoxelState::Free);
  EXPECT_EQ(band.stateAt(Vec3(0.55, 0.05, 0.65)), VoxelState::Occupied);
  EXPECT_EQ(band.stateAt(Vec3(0.55, 0.05, -0.05)), VoxelState::Occupied);
}
