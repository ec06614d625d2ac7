#include "support/test_worlds.hpp"

namespace ussnav::test {

namespace {
void rectWalls(World& w, double x0, double y0, double x1, double y1, double h) {
  const Vec2 c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (int i = 0; i < 4; ++i) {
    Wall wall;
    wall.a = c[i];
    wall.b = c[(i + 1) % 4];
    wall.thickness = 0.1;
    wall.z1 = h;
    w.walls.push_back(wall);
  }
}
Room rect(int id, const std::string& type, double x0, double y0, double x1, double y1, double h) {
  Room r;
  r.id = id;
  r.type = type;
  r.polygon = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  r.ceiling_z = h;
  return r;
}
}  // namespace

World boxRoom(double w, double d, double h) {
  World world;
  world.name = "box";
  world.rooms.push_back(rect(1, "office", 0, 0, w, d, h));
  rectWalls(world, 0, 0, w, d, h);
  world.start.position = Vec3(w / 2, d / 2, 1.2);
  return world;
}

World twoRooms(bool with_door) {
  World world;
  world.name = "two_rooms";
  world.rooms.push_back(rect(1, "office", 0, 0, 5, 4, 2.8));
  world.rooms.push_back(rect(2, "kitchen", 5, 0, 10, 4, 2.8));
  rectWalls(world, 0, 0, 10, 4, 2.8);
  Wall mid;
  mid.a = Vec2(5, 0);
  mid.b = Vec2(5, 4);
  mid.thickness = 0.1;
  mid.z1 = 2.8;
  if (with_door) {
    mid.openings.push_back(Opening{1.5, 2.5, 0.0, 2.1});
    Door d;
    d.id = 1;
    d.room_a = 1;
    d.room_b = 2;
    d.center = Vec2(5, 2);
    d.width = 1.0;
    world.doors.push_back(d);
  }
  world.walls.push_back(mid);
  world.start.position = Vec3(2.5, 2, 1.2);
  return world;
}

int addObject(World& w, const std::string& category, const Vec3& center, const Vec3& half, double yaw) {
  Object o;
  o.id = int(w.objects.size()) + 1;
  o.category = category;
  o.box.center = center;
  o.box.half_extents = half;
  o.box.yaw = yaw;
  const Room* r = w.roomAt(Vec2(center.x(), center.y()));
  o.room_id = r ? r->id : -1;
  w.objects.push_back(o);
  return o.id;
}

}  // namespace ussnav::test
