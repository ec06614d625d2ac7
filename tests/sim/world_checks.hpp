#pragma once
// Independent checks of generated worlds, shared by the sim tests: door graph connectivity,
// doors on shared walls, room overlap by sampling, and free-space reachability on a grid.

#include <string>
#include <vector>

#include "ussnav/sim/world.hpp"

namespace ussnav::test {

// Rooms reachable from the first room through doors (BFS over the door graph).
int roomsReachableByDoors(const World& w);

// "" when `d` sits on a wall whose two sides are its two rooms and that wall has an opening
// of the door's width and height around the door's centre; else what is wrong.
std::string doorProblem(const World& w, const Door& d);

// Sample points (0.25 m lattice, off the 0.1 m lattice) that lie in more than one room.
int roomOverlapSamples(const World& w);

// Free-space grid at flight height: cells inside a room, farther than `radius` from every
// wall's solid part and every object footprint. Returns, from the start pose, the number of
// rooms with no reachable cell and objects with no reachable cell within `approach` m.
struct Reachability {
  bool start_free = false;
  std::vector<int> unreachable_rooms;
  std::vector<int> unreachable_objects;
};
Reachability checkReachability(const World& w, double radius, double approach);

}  // namespace ussnav::test
