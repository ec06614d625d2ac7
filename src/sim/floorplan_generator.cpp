#include "ussnav/sim/floorplan_generator.hpp"

#include <cmath>
#include <stdexcept>

#include "floorplan_internal.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/layout_geometry.hpp"

namespace ussnav {

namespace {

void check(bool ok, const std::string& field, const std::string& what) {
  if (!ok) throw InputError("generator", field, what);
}

void validate(const GeneratorParams& p) {
  check(p.style == "office" || p.style == "apartment", "style", "expected office or apartment, got '" + p.style + "'");
  check(p.target_rooms == 0 || (p.target_rooms >= kMinGeneratedRooms && p.target_rooms <= kMaxGeneratedRooms),
        "rooms", "expected 0 (any) or " + std::to_string(kMinGeneratedRooms) + ".." +
                     std::to_string(kMaxGeneratedRooms) + ", got " + std::to_string(p.target_rooms));
  check(std::isfinite(p.target_area_m2) && p.target_area_m2 >= 0 && p.target_area_m2 <= 5000, "area",
        "expected 0 (any) or a floor area up to 5000 m^2");
  check(std::isfinite(p.ceiling_height) && p.ceiling_height >= 2.3 && p.ceiling_height <= 6.0, "ceiling_height",
        "expected 2.3..6 m (doors are 2.1 m high)");
  check(std::isfinite(p.wall_thickness) && p.wall_thickness >= 0.05 && p.wall_thickness <= 0.3, "wall_thickness",
        "expected 0.05..0.3 m");
  check(std::isfinite(p.flight_height) && p.flight_height > 0.2 && p.flight_height < p.ceiling_height - 0.3,
        "flight_height", "expected between 0.2 m and 0.3 m under the ceiling");
  check(std::isfinite(p.uav_radius) && p.uav_radius >= 0.05 && p.uav_radius <= 0.4, "uav_radius",
        "expected 0.05..0.4 m (doors are at least 0.9 m wide)");
}

}  // namespace

World generateWorld(const GeneratorParams& params) {
  validate(params);
  Rng rng(params.seed);
  const bool office = params.style == "office";
  const int rooms = params.target_rooms > 0 ? params.target_rooms : office ? rng.uniformInt(12, 26) : rng.uniformInt(9, 20);
  const double area = std::max(kMinGeneratedArea * 1.02, params.target_area_m2);
  const floorplan::Plan plan = office ? floorplan::planOffice(rooms, area, rng) : floorplan::planApartment(rooms, area, rng);
  World w;
  w.name = params.style + "-" + std::to_string(params.seed);
  w.source = "generator:" + params.style + ":seed=" + std::to_string(params.seed) + ":rooms=" + std::to_string(rooms);
  w.has_floor = true;
  floorplan::buildStructure(plan, params, rng, w);
  if (params.furnish) floorplan::furnish(params, rng, w);
  w.start = floorplan::chooseStart(w, plan.start_type, params);
  return w;
}

OrientedBox doorClearZone(const World& world, const Door& door, int room_id) {
  const Room* room = world.room(room_id);
  if (!room || (door.room_a != room_id && door.room_b != room_id))
    throw std::invalid_argument("doorClearZone: room " + std::to_string(room_id) + " is not beside door " +
                                std::to_string(door.id));
  // The door lies on the room's boundary: its nearest edge gives the wall direction.
  const auto& poly = room->polygon;
  size_t edge = 0;
  double best = 1e300;
  for (size_t i = 0; i < poly.size(); ++i) {
    const double d = pointSegmentDistance(door.center, poly[i], poly[(i + 1) % poly.size()]);
    if (d < best) best = d, edge = i;
  }
  const Vec2 dir = (poly[(edge + 1) % poly.size()] - poly[edge]).normalized();
  Vec2 n(-dir.y(), dir.x());
  if (!pointInPolygon(door.center + 0.3 * n, poly)) n = -n;
  const Vec2 c = door.center + 0.5 * kDoorClearDepth * n;
  OrientedBox z;
  z.center = Vec3(c.x(), c.y(), 0.5 * (room->floor_z + room->ceiling_z));
  z.half_extents = Vec3(0.5 * door.width + kDoorClearSide, 0.5 * kDoorClearDepth, 0.5 * (room->ceiling_z - room->floor_z));
  z.yaw = std::atan2(dir.y(), dir.x());
  return z;
}

}  // namespace ussnav
