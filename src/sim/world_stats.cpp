#include "ussnav/sim/world_stats.hpp"

#include <cmath>
#include <sstream>

namespace ussnav {

WorldStats computeWorldStats(const World& w) {
  WorldStats s;
  s.name = w.name;
  s.source = w.source;
  s.rooms = int(w.rooms.size());
  s.objects = int(w.objects.size());
  s.doors = int(w.doors.size());
  s.walls = int(w.walls.size());
  s.obstacle_voxels = w.obstacles.cells.size();
  s.bounds = w.bounds();
  for (const auto& r : w.rooms) {
    const double a = std::abs(polygonArea(r.polygon));
    ++s.rooms_by_type[r.type];
    s.area_by_type_m2[r.type] += a;
    s.floor_area_m2 += a;
    s.room_volume_m3 += a * (r.ceiling_z - r.floor_z);
  }
  for (const auto& o : w.objects) {
    ++s.objects_by_category[o.category];
    const Room* in = w.room(o.room_id);
    if (!in) in = w.roomAt(Vec2(o.box.center.x(), o.box.center.y()));
    if (in) s.object_volume_m3 += 8.0 * o.box.half_extents.prod();
  }
  s.free_volume_m3 = std::max(0.0, s.room_volume_m3 - s.object_volume_m3);
  return s;
}

namespace {
double r3(double v) { return std::round(v * 1000.0) / 1000.0; }
}  // namespace

nlohmann::json worldStatsToJson(const WorldStats& s) {
  nlohmann::json j;
  j["name"] = s.name;
  j["source"] = s.source;
  j["rooms"] = s.rooms;
  j["rooms_by_type"] = s.rooms_by_type;
  j["objects"] = s.objects;
  j["objects_by_category"] = s.objects_by_category;
  j["doors"] = s.doors;
  j["walls"] = s.walls;
  nlohmann::json area = nlohmann::json::object();
  for (const auto& [t, a] : s.area_by_type_m2) area[t] = r3(a);
  j["area_by_type_m2"] = area;
  j["floor_area_m2"] = r3(s.floor_area_m2);
  j["room_volume_m3"] = r3(s.room_volume_m3);
  j["object_volume_m3"] = r3(s.object_volume_m3);
  j["free_volume_m3"] = r3(s.free_volume_m3);
  j["obstacle_voxels"] = s.obstacle_voxels;
  if (!s.bounds.empty())
    j["bounds"] = {{"min", {r3(s.bounds.min.x()), r3(s.bounds.min.y()), r3(s.bounds.min.z())}},
                   {"max", {r3(s.bounds.max.x()), r3(s.bounds.max.y()), r3(s.bounds.max.z())}}};
  return j;
}

std::string worldStatsToText(const WorldStats& s) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(1);
  o << "world " << (s.name.empty() ? "(unnamed)" : s.name);
  if (!s.source.empty()) o << "  [" << s.source << "]";
  o << "\n";
  o << "rooms: " << s.rooms << "  doors: " << s.doors << "  walls: " << s.walls << "  objects: " << s.objects;
  if (s.obstacle_voxels) o << "  obstacle voxels: " << s.obstacle_voxels;
  o << "\n";
  if (!s.bounds.empty()) {
    const Vec3 e = s.bounds.size();
    o << "extent: " << e.x() << " x " << e.y() << " x " << e.z() << " m\n";
  }
  o << "floor area: " << s.floor_area_m2 << " m^2   free volume: " << s.free_volume_m3 << " m^3 (rooms "
    << s.room_volume_m3 << " - objects " << s.object_volume_m3 << ")\n";
  if (!s.rooms_by_type.empty()) {
    o << "rooms by type:\n";
    for (const auto& [t, n] : s.rooms_by_type)
      o << "  " << t << ": " << n << " (" << s.area_by_type_m2.at(t) << " m^2)\n";
  }
  if (!s.objects_by_category.empty()) {
    o << "objects by category:\n";
    for (const auto& [c, n] : s.objects_by_category) o << "  " << c << ": " << n << "\n";
  }
  return o.str();
}

}  // namespace ussnav
