#include "ussnav/sim/world_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"

namespace ussnav {

using nlohmann::json;

namespace {

json vec(const Vec2& v) { return json::array({v.x(), v.y()}); }
json vec(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

// Reads fields with errors that name the JSON path.
class Reader {
 public:
  explicit Reader(std::string source) : src_(std::move(source)) {}
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(src_, path, what);
  }
  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(path + "." + key, "missing required field");
    return *it;
  }
  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "expected a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "expected a finite number");
    return v;
  }
  double number(const json& obj, const std::string& path, const char* key, double def) const {
    if (!obj.contains(key)) return def;
    return number(obj.at(key), path + "." + key);
  }
  int integer(const json& j, const std::string& path) const {
    if (!j.is_number_integer()) fail(path, "expected an integer");
    // get<int>() would silently wrap values outside int (an id of 2^40 is a corrupt file).
    const bool fits = j.is_number_unsigned() ? j.get<uint64_t>() <= uint64_t(std::numeric_limits<int>::max())
                                             : j.get<int64_t>() >= std::numeric_limits<int>::min() &&
                                                   j.get<int64_t>() <= std::numeric_limits<int>::max();
    if (!fits) fail(path, "expected an integer within 32-bit range");
    return j.get<int>();
  }
  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "expected a string");
    return j.get<std::string>();
  }
  const json& array(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, "expected an array");
    return j;
  }
  Vec2 vec2(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 2) fail(path, "expected [x, y]");
    return {number(j[0], path + "[0]"), number(j[1], path + "[1]")};
  }
  Vec3 vec3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, z]");
    return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
  }

 private:
  std::string src_;
};

std::string at(const std::string& base, size_t i) { return base + "[" + std::to_string(i) + "]"; }

// Approximate floor two polygons share beyond a tolerance: lattice samples (at most ~40k)
// over the intersection of their bounding boxes; a sample counts its cell when it and its four
// neighbours `tol` away lie in both polygons, so slivers thinner than 2 x tol (imprecise
// shared walls in imported plans) do not count.
double overlapArea(const std::vector<Vec2>& pa, const std::vector<Vec2>& pb, double tol) {
  Vec2 alo = pa[0], ahi = pa[0], blo = pb[0], bhi = pb[0];
  for (const auto& p : pa) alo = alo.cwiseMin(p), ahi = ahi.cwiseMax(p);
  for (const auto& p : pb) blo = blo.cwiseMin(p), bhi = bhi.cwiseMax(p);
  const Vec2 lo = alo.cwiseMax(blo), hi = ahi.cwiseMin(bhi);
  const Vec2 ext = hi - lo;
  if (ext.x() <= 0.02 || ext.y() <= 0.02) return 0.0;
  const double step = std::max(0.05, std::sqrt(ext.x() * ext.y() / 40000.0));
  const int nx = std::max(1, int(ext.x() / step)), ny = std::max(1, int(ext.y() / step));
  const double dx = ext.x() / nx, dy = ext.y() / ny;
  int hits = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p(lo.x() + (i + 0.5) * dx, lo.y() + (j + 0.5) * dy);
      auto both = [&](const Vec2& q) { return pointInPolygon(q, pa) && pointInPolygon(q, pb); };
      if (both(p) && both(p + Vec2(tol, 0)) && both(p - Vec2(tol, 0)) && both(p + Vec2(0, tol)) &&
          both(p - Vec2(0, tol)))
        ++hits;
    }
  return hits * dx * dy;
}

}  // namespace

json worldToJson(const World& w) {
  json j;
  j["format"] = "ussnav-world";
  j["version"] = World::kFormatVersion;
  j["name"] = w.name;
  j["source"] = w.source;
  j["has_floor"] = w.has_floor;
  j["start"] = {{"position", vec(w.start.position)}, {"yaw", w.start.yaw}};
  j["rooms"] = json::array();
  for (const auto& r : w.rooms) {
    json poly = json::array();
    for (const auto& p : r.polygon) poly.push_back(vec(p));
    j["rooms"].push_back({{"id", r.id}, {"type", r.type}, {"name", r.name}, {"polygon", poly},
                          {"floor_z", r.floor_z}, {"ceiling_z", r.ceiling_z}});
  }
  j["walls"] = json::array();
  for (const auto& wl : w.walls) {
    json ops = json::array();
    for (const auto& o : wl.openings)
      ops.push_back({{"start", o.start}, {"end", o.end}, {"bottom", o.bottom}, {"top", o.top}});
    j["walls"].push_back({{"a", vec(wl.a)}, {"b", vec(wl.b)}, {"thickness", wl.thickness},
                          {"z0", wl.z0}, {"z1", wl.z1}, {"openings", ops}});
  }
  j["doors"] = json::array();
  for (const auto& d : w.doors)
    j["doors"].push_back({{"id", d.id}, {"room_a", d.room_a}, {"room_b", d.room_b},
                          {"center", vec(d.center)}, {"width", d.width}, {"height", d.height}});
  j["objects"] = json::array();
  for (const auto& o : w.objects)
    j["objects"].push_back({{"id", o.id}, {"category", o.category}, {"room_id", o.room_id},
                            {"center", vec(o.box.center)}, {"half_extents", vec(o.box.half_extents)},
                            {"yaw", o.box.yaw}});
  if (!w.obstacles.cells.empty()) {
    json cells = json::array();
    for (const auto& c : w.obstacles.cells) cells.push_back(json::array({c.x(), c.y(), c.z()}));
    j["obstacles"] = {{"resolution", w.obstacles.resolution}, {"origin", vec(w.obstacles.origin)},
                      {"cells", cells}};
  }
  return j;
}

World worldFromJson(const json& j, const std::string& source) {
  Reader r(source);
  if (!j.is_object()) r.fail("", "expected a JSON object (a ussnav world)");
  // Checked as a string first: json::value() throws a type_error (not an InputError) on
  // "format": 5.
  if (!j.contains("format") || !j["format"].is_string() || j["format"].get<std::string>() != "ussnav-world")
    r.fail("format", "expected \"ussnav-world\" (is this a world file?)");
  const int version = r.integer(r.member(j, "", "version"), "version");
  if (version != World::kFormatVersion)
    r.fail("version", "unsupported version " + std::to_string(version) + "; expected " +
                          std::to_string(World::kFormatVersion));
  World w;
  w.name = j.contains("name") ? r.string(j["name"], "name") : "";
  w.source = j.contains("source") ? r.string(j["source"], "source") : "";
  if (j.contains("has_floor")) {
    if (!j["has_floor"].is_boolean()) r.fail("has_floor", "expected true or false");
    w.has_floor = j["has_floor"].get<bool>();
  }
  if (j.contains("start")) {
    w.start.position = r.vec3(r.member(j["start"], "start", "position"), "start.position");
    w.start.yaw = r.number(j["start"], "start", "yaw", 0.0);
  }
  const auto& rooms = r.array(r.member(j, "", "rooms"), "rooms");
  for (size_t i = 0; i < rooms.size(); ++i) {
    const std::string p = at("rooms", i);
    Room room;
    room.id = r.integer(r.member(rooms[i], p, "id"), p + ".id");
    room.type = r.string(r.member(rooms[i], p, "type"), p + ".type");
    if (room.type.empty()) r.fail(p + ".type", "expected a non-empty room type");
    if (rooms[i].contains("name")) room.name = r.string(rooms[i]["name"], p + ".name");
    const auto& poly = r.array(r.member(rooms[i], p, "polygon"), p + ".polygon");
    if (poly.size() < 3) r.fail(p + ".polygon", "expected at least 3 points");
    for (size_t k = 0; k < poly.size(); ++k) room.polygon.push_back(r.vec2(poly[k], at(p + ".polygon", k)));
    room.floor_z = r.number(rooms[i], p, "floor_z", 0.0);
    room.ceiling_z = r.number(rooms[i], p, "ceiling_z", 2.8);
    if (room.ceiling_z <= room.floor_z + 0.5) r.fail(p + ".ceiling_z", "expected at least 0.5 m above floor_z");
    if (std::abs(polygonArea(room.polygon)) < 0.05) r.fail(p + ".polygon", "expected a non-degenerate polygon");
    w.rooms.push_back(std::move(room));
  }
  if (j.contains("walls")) {
    const auto& walls = r.array(j["walls"], "walls");
    for (size_t i = 0; i < walls.size(); ++i) {
      const std::string p = at("walls", i);
      Wall wl;
      wl.a = r.vec2(r.member(walls[i], p, "a"), p + ".a");
      wl.b = r.vec2(r.member(walls[i], p, "b"), p + ".b");
      wl.thickness = r.number(walls[i], p, "thickness", 0.1);
      wl.z0 = r.number(walls[i], p, "z0", 0.0);
      wl.z1 = r.number(walls[i], p, "z1", 2.8);
      if (wl.thickness <= 0) r.fail(p + ".thickness", "expected a positive thickness");
      if (wl.z1 <= wl.z0) r.fail(p + ".z1", "expected z1 above z0");
      if (walls[i].contains("openings")) {
        const auto& ops = r.array(walls[i]["openings"], p + ".openings");
        for (size_t k = 0; k < ops.size(); ++k) {
          const std::string q = at(p + ".openings", k);
          Opening o;
          o.start = r.number(r.member(ops[k], q, "start"), q + ".start");
          o.end = r.number(r.member(ops[k], q, "end"), q + ".end");
          o.bottom = r.number(ops[k], q, "bottom", 0.0);
          o.top = r.number(ops[k], q, "top", 2.1);
          if (o.end <= o.start) r.fail(q + ".end", "expected end > start");
          if (o.top <= o.bottom) r.fail(q + ".top", "expected top > bottom");
          wl.openings.push_back(o);
        }
      }
      w.walls.push_back(std::move(wl));
    }
  }
  if (j.contains("doors")) {
    const auto& doors = r.array(j["doors"], "doors");
    for (size_t i = 0; i < doors.size(); ++i) {
      const std::string p = at("doors", i);
      Door d;
      d.id = r.integer(r.member(doors[i], p, "id"), p + ".id");
      d.room_a = r.integer(r.member(doors[i], p, "room_a"), p + ".room_a");
      d.room_b = r.integer(r.member(doors[i], p, "room_b"), p + ".room_b");
      d.center = r.vec2(r.member(doors[i], p, "center"), p + ".center");
      d.width = r.number(doors[i], p, "width", 0.9);
      d.height = r.number(doors[i], p, "height", 2.1);
      if (d.width <= 0 || d.height <= 0) r.fail(p + ".width", "expected positive width and height");
      w.doors.push_back(d);
    }
  }
  if (j.contains("objects")) {
    const auto& objs = r.array(j["objects"], "objects");
    for (size_t i = 0; i < objs.size(); ++i) {
      const std::string p = at("objects", i);
      Object o;
      o.id = r.integer(r.member(objs[i], p, "id"), p + ".id");
      o.category = r.string(r.member(objs[i], p, "category"), p + ".category");
      o.room_id = objs[i].contains("room_id") ? r.integer(objs[i]["room_id"], p + ".room_id") : -1;
      o.box.center = r.vec3(r.member(objs[i], p, "center"), p + ".center");
      o.box.half_extents = r.vec3(r.member(objs[i], p, "half_extents"), p + ".half_extents");
      o.box.yaw = r.number(objs[i], p, "yaw", 0.0);
      if (o.id < 1 || o.id > 65000) r.fail(p + ".id", "expected an instance id in 1..65000");
      if ((o.box.half_extents.array() <= 0).any()) r.fail(p + ".half_extents", "expected positive half extents");
      if (o.category.empty()) r.fail(p + ".category", "expected a non-empty category");
      w.objects.push_back(std::move(o));
    }
  }
  if (j.contains("obstacles")) {
    const json& ob = j["obstacles"];
    w.obstacles.resolution = r.number(r.member(ob, "obstacles", "resolution"), "obstacles.resolution");
    if (w.obstacles.resolution <= 0) r.fail("obstacles.resolution", "expected a positive voxel size");
    w.obstacles.origin = r.vec3(r.member(ob, "obstacles", "origin"), "obstacles.origin");
    const auto& cells = r.array(r.member(ob, "obstacles", "cells"), "obstacles.cells");
    w.obstacles.cells.reserve(cells.size());
    for (size_t i = 0; i < cells.size(); ++i) {
      const auto& c = cells[i];
      if (!c.is_array() || c.size() != 3 || !c[0].is_number_integer() || !c[1].is_number_integer() ||
          !c[2].is_number_integer())
        r.fail(at("obstacles.cells", i), "expected [i, j, k] integers");
      const std::string q = at("obstacles.cells", i);
      w.obstacles.cells.emplace_back(r.integer(c[0], q + "[0]"), r.integer(c[1], q + "[1]"), r.integer(c[2], q + "[2]"));
    }
  }
  if (w.rooms.empty() && w.obstacles.cells.empty())
    r.fail("rooms", "a world needs at least one room or obstacle voxels");
  validateWorld(w, source);
  return w;
}

void validateWorld(const World& w, const std::string& source) {
  std::set<int> room_ids, object_ids, door_ids;
  for (size_t i = 0; i < w.rooms.size(); ++i)
    if (!room_ids.insert(w.rooms[i].id).second)
      throw InputError(source, at("rooms", i) + ".id", "duplicate room id " + std::to_string(w.rooms[i].id));
  // Overlap: rooms may share walls (touching boundaries) but not floor. An overlap at least
  // 20 cm thick and larger than 0.05 m^2 is an error; thinner slivers along a shared wall are
  // tolerated (imported plans are rarely exact).
  for (size_t i = 0; i < w.rooms.size(); ++i)
    for (size_t k = i + 1; k < w.rooms.size(); ++k) {
      const auto& a = w.rooms[i];
      const auto& b = w.rooms[k];
      const bool z_overlap = a.floor_z < b.ceiling_z - 0.1 && b.floor_z < a.ceiling_z - 0.1;
      if (!z_overlap) continue;
      const double area = overlapArea(a.polygon, b.polygon, 0.1);
      if (area > 0.05) {
        char shared[32];
        std::snprintf(shared, sizeof shared, "%.2f", area);
        throw InputError(source, at("rooms", k) + ".polygon",
                         "overlaps " + at("rooms", i) + " (id " + std::to_string(a.id) + ", about " + shared +
                             " m^2 of shared floor); rooms must not overlap, only share walls");
      }
    }
  for (size_t i = 0; i < w.doors.size(); ++i) {
    const auto& d = w.doors[i];
    if (!door_ids.insert(d.id).second)
      throw InputError(source, at("doors", i) + ".id", "duplicate door id");
    for (int rid : {d.room_a, d.room_b})
      if (rid != -1 && !room_ids.count(rid))
        throw InputError(source, at("doors", i), "refers to unknown room id " + std::to_string(rid));
    if (d.room_a == d.room_b)
      throw InputError(source, at("doors", i), "expected two different rooms");
  }
  for (size_t i = 0; i < w.objects.size(); ++i) {
    const auto& o = w.objects[i];
    if (!object_ids.insert(o.id).second)
      throw InputError(source, at("objects", i) + ".id", "duplicate object id " + std::to_string(o.id));
    if (w.rooms.empty()) continue;
    const Vec2 c(o.box.center.x(), o.box.center.y());
    const Room* in = w.roomAt(c);
    if (!in)
      throw InputError(source, at("objects", i), "object '" + o.category + "' (id " + std::to_string(o.id) +
                                                     ") is outside every room");
    if (o.room_id != -1 && !room_ids.count(o.room_id))
      throw InputError(source, at("objects", i) + ".room_id", "unknown room id " + std::to_string(o.room_id));
  }
}

void saveWorld(const World& w, const std::filesystem::path& path) {
  writeFileAtomic(path, worldToJson(w).dump(1) + "\n");
}

World loadWorld(const std::filesystem::path& path) {
  return worldFromJson(readJsonFile(path), path.string());
}

}  // namespace ussnav
