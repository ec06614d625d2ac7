#pragma once
// Seeded floor-plan generator: an office floor (one or two corridors with offices, meeting
// rooms, kitchen, bathrooms, storage) or a large apartment (one big flat or two flats joined
// by their hallways), furnished from the object table (object_table.hpp). Same params => same
// World, byte for byte once saved. Every room is reachable through doors; objects keep clear of
// walls, of each other and of the zone in front of every door, and leave each room navigable
// for a UAV of `uav_radius`. Cost: about 5-60 ms per world (median ~15 ms), dominated by
// the navigability checks of object placement.

#include <cstdint>
#include <string>

#include "ussnav/sim/world.hpp"

namespace ussnav {

struct GeneratorParams {
  std::string style = "office";  // office | apartment
  uint64_t seed = 1;
  int target_rooms = 0;          // 0 = drawn from the seed; else 6..30, honoured exactly
  double target_area_m2 = 0.0;   // 0 = as the rooms need; the floor is never below 300 m^2
  double ceiling_height = 2.8;   // m; also the wall height
  double wall_thickness = 0.12;  // m
  double flight_height = 1.2;    // m above the floor, for world.start
  double uav_radius = 0.25;      // m, navigability check when placing objects
  bool furnish = true;           // place objects
};

constexpr int kMinGeneratedRooms = 6;
constexpr int kMaxGeneratedRooms = 30;
constexpr double kMinGeneratedArea = 300.0;  // m^2
constexpr double kDoorClearDepth = 1.0;      // m kept free in front of a door, inside each room
constexpr double kDoorClearSide = 0.2;       // m the clear zone extends past each door jamb

// Throws InputError("generator", "<param>", reason) for an unknown style or out-of-range value.
World generateWorld(const GeneratorParams& params);

// The zone kept free of objects in front of `door` on the side of room `room_id`: a box of
// (width + 2 * kDoorClearSide) x kDoorClearDepth from the wall line into the room, full
// height. Requires room_id to be one of the door's rooms.
OrientedBox doorClearZone(const World& world, const Door& door, int room_id);

}  // namespace ussnav
