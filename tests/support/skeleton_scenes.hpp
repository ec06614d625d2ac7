#pragma once
// Hand-made scenes for the skeleton tests and benchmark, on DenseGrid: a box room, two rooms
// joined by one door, a corridor, a floor of rooms with doors; plus a range-sensor emulation
// that reveals a scene voxel by voxel, for incremental and rolling-window cases.

#include <vector>

#include "support/dense_grid.hpp"

namespace ussnav::test {

// Solid everywhere except the carved free space: walls, floor and ceiling are occupied.
struct BoxRoomScene {
  DenseGrid grid;
  Aabb room;  // free interior
};
BoxRoomScene boxRoomGrid(const Vec3& size = Vec3(4.0, 4.0, 2.6), double resolution = 0.1);

// Room A: x in [0, 4], room B: x in [4.2, 8.2], y in [0, 4], z in [0, 2.6], separated by a wall
// at x in [wall_min_x, wall_max_x] with one 0.9 x 2.0 m door (a free box through the wall).
struct TwoRoomsScene {
  DenseGrid grid;
  Aabb room_a, room_b, door;
  double wall_min_x = 0, wall_max_x = 0;
};
TwoRoomsScene twoRoomsGrid(double resolution = 0.1);

// A straight corridor along x: [0, length] x [0, width] x [0, height].
struct CorridorScene {
  DenseGrid grid;
  Aabb corridor;
};
CorridorScene corridorGrid(double length = 10.0, double width = 1.2, double height = 2.4,
                       double resolution = 0.1);

// A floor of nx x ny rooms (room_size each, 0.2 m walls) with a 0.9 x 2.0 m door in every
// interior wall, off-centre so the pattern is not symmetric.
struct FloorScene {
  DenseGrid grid;
  std::vector<Aabb> rooms;
  std::vector<Aabb> doors;
};
FloorScene floorGrid(int nx, int ny, double room_size = 4.0, double height = 2.6,
                     double resolution = 0.1);

// Emulates a range sensor: from `origin`, `rays` rays (Fibonacci directions) up to `range` walk
// `truth`; the voxels they cross become Free in `known` and the voxel that stops them Occupied.
void observe(const DenseGrid& truth, DenseGrid& known, const Vec3& origin, double range, int rays);

// Points every `step` metres (or closer) along the polyline through `waypoints`.
std::vector<Vec3> samplePolyline(const std::vector<Vec3>& waypoints, double step);

}  // namespace ussnav::test
