#pragma once
// Internal to the floor-plan generator: a plan is rooms made of axis-aligned rectangles on a
// 0.1 m lattice (integer decimetres, so shared walls match exactly), plus the style's door
// policy. floorplan_layout.cpp turns a plan into rooms, walls and doors; object_placement.cpp
// furnishes the rooms.

#include <string>
#include <vector>

#include "ussnav/core/random.hpp"
#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav::floorplan {

struct RectDm {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // decimetres, x0 < x1, y0 < y1
};

struct PlanRoom {
  std::string type;
  std::vector<RectDm> rects;  // union is simply connected; rects do not overlap
  int group = 0;              // a flat of an apartment; doors stay inside a group unless allowed
};

struct DoorPolicy {
  // Every room not of circulation[0] gets a door to an adjacent room of the first type in this
  // list that it touches (corridor; hallway, then living room).
  std::vector<std::string> circulation;
  struct Extra {
    std::string a, b;
    double probability = 0.0;
    bool cross_group = false;  // may join rooms of different groups (hallway to hallway)
  };
  std::vector<Extra> extra;                 // further doors between adjacent types
  std::vector<std::string> two_door_types;  // a second door to circulation when the wall is long
};

struct Plan {
  std::vector<PlanRoom> rooms;  // room id = index + 1
  DoorPolicy doors;
  std::string start_type;       // where world.start goes (corridor, hallway)
};

Plan planOffice(int rooms, double min_area_m2, Rng& rng);
Plan planApartment(int rooms, double min_area_m2, Rng& rng);

// A wall segment on the boundary between two rooms (or a room and the outside, -1).
struct PlanWall {
  int room_a = -1, room_b = -1;  // room ids, room_a < room_b (-1 first)
  Vec2 a, b;                     // metres, on the shared boundary line
  int world_wall = -1;           // index into World::walls
};

// Rooms (CCW polygons), walls (extended by half a thickness at both ends so junctions close)
// and doors following the plan's policy; every room ends up reachable from every other.
void buildStructure(const Plan& plan, const GeneratorParams& params, Rng& rng, World& world);

// Outline of a union of rectangles, counter-clockwise, collinear points removed, metres.
std::vector<Vec2> outlineDm(const std::vector<RectDm>& rects);

// Places objects room by room (object_table.hpp), with the navigability checks.
void furnish(const GeneratorParams& params, Rng& rng, World& world);

// A free pose at flight height in the largest room of `room_type` (else the largest room):
// the reachable spot farthest from walls and objects, nearest the room's middle among ties,
// facing along the room's long axis.
Pose chooseStart(const World& world, const std::string& room_type, const GeneratorParams& params);

}  // namespace ussnav::floorplan
