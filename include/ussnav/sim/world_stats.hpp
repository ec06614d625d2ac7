#pragma once
// Summary numbers of a world for `ussnav world stats`: rooms and objects by kind, floor area
// and free volume. Definitions (docs/world-format.md): floor area = sum of |room polygon area|
// (polygons run along wall centre lines); free volume = sum over rooms of area x (ceiling -
// floor) minus the box volume of every object inside a room. Linear in rooms + objects.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "ussnav/sim/world.hpp"

namespace ussnav {

struct WorldStats {
  std::string name, source;
  int rooms = 0, objects = 0, doors = 0, walls = 0;
  std::map<std::string, int> rooms_by_type;
  std::map<std::string, int> objects_by_category;
  std::map<std::string, double> area_by_type_m2;
  double floor_area_m2 = 0.0;
  double room_volume_m3 = 0.0;    // sum of area x height over rooms
  double object_volume_m3 = 0.0;  // boxes of objects inside some room
  double free_volume_m3 = 0.0;    // room_volume_m3 - object_volume_m3
  size_t obstacle_voxels = 0;
  Aabb bounds;
};

WorldStats computeWorldStats(const World& world);
// One JSON object; keys as the struct fields (numbers rounded to 0.001).
nlohmann::json worldStatsToJson(const WorldStats& stats);
// Human-readable multi-line summary.
std::string worldStatsToText(const WorldStats& stats);

}  // namespace ussnav
