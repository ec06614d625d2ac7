#pragma once
// The simulator's world: rooms (typed footprints), walls with door openings, doors joining
// rooms, objects as oriented boxes, and optional raw obstacle voxels (for scanned buildings
// that have no room model). Plain data; building it lives in generators/importers, reading and
// writing in world_io, rasterising in ground_truth. This is ground truth: the navigation
// pipeline never reads it, only the simulator and the evaluation do.

#include <string>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

struct Room {
  int id = 0;
  std::string type;             // e.g. "office", "corridor", "bedroom" (lower case, spaces)
  std::string name;             // optional human name, e.g. "ROOM_1"
  std::vector<Vec2> polygon;    // footprint, counter-clockwise, metres
  double floor_z = 0.0;
  double ceiling_z = 2.8;
};

// An opening in a wall, measured along the wall from its start point `a`.
struct Opening {
  double start = 0.0, end = 0.0;   // metres along the wall
  double bottom = 0.0, top = 2.1;  // metres above the wall's base z
};

struct Wall {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  double thickness = 0.1;
  double z0 = 0.0, z1 = 2.8;
  std::vector<Opening> openings;
};

struct Door {
  int id = 0;
  int room_a = -1, room_b = -1;  // room ids; -1 = outside
  Vec2 center = Vec2::Zero();    // middle of the opening, on the wall line
  double width = 0.9;
  double height = 2.1;
};

// Oriented box: centre, half extents along its own axes, yaw about +z.
struct OrientedBox {
  Vec3 center = Vec3::Zero();
  Vec3 half_extents = Vec3::Constant(0.25);
  double yaw = 0.0;
  bool contains(const Vec3& p, double margin = 0.0) const;
  Aabb bounds() const;
  // Distance from p to the box surface (0 inside).
  double distance(const Vec3& p) const;
};

struct Object {
  int id = 0;                // instance id, unique in the world, >= 1
  std::string category;      // lower case, e.g. "bed", "chair", "whiteboard"
  int room_id = -1;          // -1 when the world has no rooms
  OrientedBox box;
};

// Occupied voxels given directly (scans): cell (i,j,k) covers origin + [i,i+1)*resolution.
struct ObstacleVoxels {
  double resolution = 0.1;
  Vec3 origin = Vec3::Zero();
  std::vector<Vec3i> cells;
};

struct World {
  static constexpr int kFormatVersion = 1;
  std::string name;
  std::string source;        // "generator:office:seed=3", "procthor:house_0.json", ...
  std::vector<Room> rooms;
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<Object> objects;
  ObstacleVoxels obstacles;  // empty unless imported from a scan
  bool has_floor = true;     // add floor and ceiling slabs under/over every room
  Pose start;                // default start pose for episodes

  const Room* room(int id) const;
  const Object* object(int id) const;
  // Room whose footprint contains (x, y), or nullptr.
  const Room* roomAt(const Vec2& p) const;
  // Bounds of everything (rooms, walls, objects, obstacle voxels).
  Aabb bounds() const;
};

// Polygon helpers (free functions: pure geometry).
double polygonArea(const std::vector<Vec2>& poly);         // signed, CCW positive
bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& poly);
Vec2 polygonCentroid(const std::vector<Vec2>& poly);

}  // namespace ussnav
