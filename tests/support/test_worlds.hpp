#pragma once
// Small hand-made worlds for simulator tests: a box room, two rooms joined by a door (or not),
// a room with objects. Each states its exact geometry so tests can compare with analytic values.

#include "ussnav/sim/world.hpp"

namespace ussnav::test {

// One room [0, w] x [0, d], floor 0, ceiling h, four walls 0.1 m thick centred on the edges.
World boxRoom(double w = 6.0, double d = 4.0, double h = 2.8);
// Rooms A = [0,5]x[0,4] and B = [5,10]x[0,4]; the wall x = 5 has a door at y in [1.5, 2.5]
// when `with_door`, otherwise it is solid.
World twoRooms(bool with_door = true);
// Adds an axis-aligned object box with the given centre and half extents; returns its id.
int addObject(World& w, const std::string& category, const Vec3& center, const Vec3& half, double yaw = 0.0);

}  // namespace ussnav::test
