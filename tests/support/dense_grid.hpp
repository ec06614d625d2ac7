#pragma once
// A dense hand-made occupancy grid for tests and benchmarks: an OccupancyMap over a fixed box,
// with helpers that carve free boxes, put walls and doors, mark unknown regions, and a movable
// "window" that hides everything outside it (to emulate the rolling grid). Plus a few scenes
// (box room, two rooms with a door, corridor, multi-room floor) described by plain structs.

#include <cstdint>
#include <vector>

#include "ussnav/mapping/occupancy.hpp"

namespace ussnav::test {

class DenseGrid : public OccupancyMap {
 public:
  // Voxels covering `bounds` (rounded outwards to the voxel lattice), all set to `fill`.
  DenseGrid(const Aabb& bounds, double resolution, VoxelState fill = VoxelState::Unknown);

  double resolution() const override { return res_; }
  VoxelState state(const Vec3i& key) const override;
  bool inWindow(const Vec3i& key) const override;
  Aabb window() const override;

  // Sets every voxel whose centre lies in `box`.
  void fill(const Aabb& box, VoxelState s);
  void carve(const Aabb& box) { fill(box, VoxelState::Free); }
  void wall(const Aabb& box) { fill(box, VoxelState::Occupied); }
  void hide(const Aabb& box) { fill(box, VoxelState::Unknown); }
  void set(const Vec3i& key, VoxelState s);
  // Restricts the map to `w` (state Unknown, inWindow false outside); resetWindow() undoes it.
  void setWindow(const Aabb& w);
  void resetWindow();
  // Voxel count in a state (inside the window only).
  size_t count(VoxelState s) const;
  const Aabb& bounds() const { return bounds_; }
  // The state stored for `key`, ignoring the window (Unknown outside the grid).
  VoxelState stored(const Vec3i& key) const;
  // Keys in the window, for loops over all voxels.
  Vec3i minKey() const { return win_lo_; }
  Vec3i maxKey() const { return win_hi_; }  // inclusive

 private:
  bool inGrid(const Vec3i& k) const;
  size_t index(const Vec3i& k) const;
  double res_;
  Aabb bounds_;
  Vec3i lo_, dims_;
  Vec3i win_lo_, win_hi_;
  std::vector<uint8_t> cells_;
};

// Solid everywhere except the carved free space: walls, floor and ceiling are occupied.
struct BoxRoomScene {
  DenseGrid grid;
  Aabb room;  // free interior
};
BoxRoomScene boxRoom(const Vec3& size = Vec3(4.0, 4.0, 2.6), double resolution = 0.1);

// Two rooms side by side along x, separated by a wall at x in [wall_min_x, wall_max_x] with one
// door (a free box through the wall).
struct TwoRoomsScene {
  DenseGrid grid;
  Aabb room_a, room_b, door;
  double wall_min_x = 0, wall_max_x = 0;
};
TwoRoomsScene twoRooms(double resolution = 0.1);

// A straight corridor along x.
struct CorridorScene {
  DenseGrid grid;
  Aabb corridor;
};
CorridorScene corridor(double length = 10.0, double width = 1.2, double height = 2.4,
                       double resolution = 0.1);

// A floor of `nx` x `ny` rooms (room_size each) on a grid of walls, with a door in every
// interior wall, for benchmarks and larger tests.
struct FloorScene {
  DenseGrid grid;
  std::vector<Aabb> rooms;
  std::vector<Aabb> doors;
};
FloorScene roomFloor(int nx, int ny, double room_size = 4.0, double height = 2.6,
                     double resolution = 0.1);

// Emulates a range sensor: from `origin`, `rays` rays (Fibonacci directions) up to `range` walk
// `truth`; the voxels they cross become Free in `known` and the voxel that stops them Occupied.
void observe(const DenseGrid& truth, DenseGrid& known, const Vec3& origin, double range, int rays);

// Points every `step` metres along the polyline through `waypoints`.
std::vector<Vec3> samplePolyline(const std::vector<Vec3>& waypoints, double step);

}  // namespace ussnav::test
