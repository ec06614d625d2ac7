#include "ussnav/sim/importers/procthor.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "import_util.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {

using nlohmann::json;
using importers::JsonFields;

namespace {

struct Asset {
  std::string type;  // objectType, e.g. "DiningTable"
  Vec3 size;         // Unity bounding box x, y (up), z
};
using AssetDb = std::unordered_map<std::string, Asset>;

AssetDb loadAssetDb(const std::filesystem::path& path) {
  AssetDb db;
  if (path.extension() == ".tsv") {
    const auto t = importers::readTsv(path, {"assetId", "objectType", "bbox_x", "bbox_y", "bbox_z"});
    const int id = t.column("assetId"), ty = t.column("objectType");
    const int bx = t.column("bbox_x"), by = t.column("bbox_y"), bz = t.column("bbox_z");
    for (size_t r = 0; r < t.rows.size(); ++r)
      db[t.cell(r, id)] = {t.cell(r, ty), Vec3(t.number(r, bx), t.number(r, by), t.number(r, bz))};
    return db;
  }
  // asset-database.json: {objectType: [{assetId, boundingBox: {x, y, z}}, ...], ...}
  const json j = readJsonFile(path);
  const JsonFields f(path.string());
  if (!j.is_object()) f.fail("", "expected an object of objectType -> [assets]");
  for (const auto& [type, assets] : j.items()) {
    if (!assets.is_array()) f.fail(type, "expected an array of assets");
    for (size_t i = 0; i < assets.size(); ++i) {
      const std::string p = type + "[" + std::to_string(i) + "]";
      const json& bb = f.member(assets[i], p, "boundingBox");
      db[f.string(assets[i], p, "assetId")] = {type, Vec3(f.number(bb, p + ".boundingBox", "x"),
                                                          f.number(bb, p + ".boundingBox", "y"),
                                                          f.number(bb, p + ".boundingBox", "z"))};
    }
  }
  return db;
}

std::filesystem::path findAssetDb(const std::filesystem::path& house, const ImportOptions& opt) {
  if (!opt.asset_database.empty()) return opt.asset_database;
  const auto dir = house.has_parent_path() ? house.parent_path() : std::filesystem::path(".");
  for (const auto& base : {dir, dir.parent_path()})
    for (const char* name : {"asset_bboxes.tsv", "asset-database.json"})
      if (std::filesystem::exists(base / name)) return base / name;
  throw InputError(house.string(), "objects[].assetId",
                   "no asset database (asset_bboxes.tsv or asset-database.json) beside the house "
                   "or one folder up; pass one explicitly");
}

// "room|4" -> 4. ProcTHOR numbers rooms itself; keeping its numbers keeps ids traceable.
int roomNumber(const std::string& id, const JsonFields& f, const std::string& path) {
  const size_t bar = id.rfind('|');
  try {
    size_t used = 0;
    const int n = std::stoi(id.substr(bar == std::string::npos ? 0 : bar + 1), &used);
    if (used > 0) return n;
  } catch (const std::exception&) {
  }
  f.fail(path, "expected a room id like \"room|4\", got \"" + id + "\"");
}

std::string roomType(const std::string& t) {
  static const std::map<std::string, std::string> kTypes{
      {"Bedroom", "bedroom"}, {"Bathroom", "bathroom"}, {"Kitchen", "kitchen"}, {"LivingRoom", "living room"}};
  return importers::categoryFromTypeName(t, kTypes);
}

// ProcTHOR objectType -> our category words.
std::string objectCategory(const std::string& type) {
  static const std::map<std::string, std::string> kNames{
      {"Television", "tv"},        {"ArmChair", "armchair"}, {"TVStand", "tv stand"},
      {"CounterTop", "countertop"}, {"BasketBall", "basketball"}, {"KeyChain", "keychain"},
      {"CD", "cd"}};
  return importers::categoryFromTypeName(type, kNames);
}

Vec3 unityPoint(const json& p, const JsonFields& f, const std::string& path) {
  return {f.number(p, path, "x"), f.number(p, path, "y"), f.number(p, path, "z")};
}
Vec2 plan(const Vec3& u) { return {u.x(), u.z()}; }  // Unity (x, z) -> our (x, y)

struct RawWall {
  Vec2 origin, dir;  // polygon[0] and the unit direction to the other end (door holes use it)
  Vec2 a, b;
  double z0 = 0, z1 = 0;
  bool empty = false;
  int room = 0;
};

RawWall readWall(const json& w, const JsonFields& f, const std::string& p) {
  const json& poly = f.array(w, p, "polygon");
  if (poly.size() < 3) f.fail(p + ".polygon", "expected the 4 corners of a wall");
  RawWall r;
  r.z0 = std::numeric_limits<double>::infinity();
  r.z1 = -r.z0;
  std::vector<Vec2> ends;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec3 u = unityPoint(poly[k], f, p + ".polygon[" + std::to_string(k) + "]");
    r.z0 = std::min(r.z0, u.y());
    r.z1 = std::max(r.z1, u.y());
    const Vec2 q = plan(u);
    if (std::none_of(ends.begin(), ends.end(), [&](const Vec2& e) { return (e - q).norm() < 1e-4; }))
      ends.push_back(q);
  }
  if (ends.size() != 2 || r.z1 - r.z0 < 0.1) f.fail(p + ".polygon", "expected a vertical rectangle (2 ends, some height)");
  r.origin = r.a = ends[0];
  r.b = ends[1];
  r.dir = (r.b - r.a).normalized();
  r.empty = w.contains("empty") && w["empty"].is_boolean() && w["empty"].get<bool>();
  r.room = roomNumber(f.string(w, p, "roomId"), f, p + ".roomId");
  return r;
}

// The two sides of one physical wall share a key: its ends rounded to millimetres, sorted.
std::string wallKey(const Vec2& a, const Vec2& b) {
  auto mm = [](const Vec2& v) { return std::make_pair(std::lround(v.x() * 1000), std::lround(v.y() * 1000)); };
  auto p = mm(a), q = mm(b);
  if (q < p) std::swap(p, q);
  std::ostringstream s;
  s << p.first << ',' << p.second << ';' << q.first << ',' << q.second;
  return s.str();
}

struct WallGroup {
  Wall wall;
  std::set<int> rooms;
  bool all_empty = true;
};

// Box of an object: centre = position (the asset box centre), sizes from the database. Objects
// tilted about x or z (leaning bats) get the axis-aligned bounds of the tilted box instead.
OrientedBox objectBox(const Vec3& pos, const Vec3& rot_deg, const Vec3& size) {
  OrientedBox b;
  b.center = Vec3(pos.x(), pos.z(), pos.y());
  const double tilt = std::max(std::abs(std::remainder(rot_deg.x(), 360.0)), std::abs(std::remainder(rot_deg.z(), 360.0)));
  if (tilt < 1.0) {
    b.half_extents = Vec3(size.x(), size.z(), size.y()) * 0.5;
    b.yaw = wrapAngle(-deg2rad(rot_deg.y()));
    return b;
  }
  // Unity applies z, then x, then y (left-handed; the AABB does not care about the handedness).
  const Mat3 r = (Eigen::AngleAxisd(deg2rad(rot_deg.y()), Vec3::UnitY()) *
                  Eigen::AngleAxisd(deg2rad(rot_deg.x()), Vec3::UnitX()) *
                  Eigen::AngleAxisd(deg2rad(rot_deg.z()), Vec3::UnitZ())).toRotationMatrix();
  const Vec3 e = r.cwiseAbs() * (0.5 * size);
  b.half_extents = Vec3(e.x(), e.z(), e.y());
  b.yaw = 0.0;
  return b;
}

// A child the box of its receptacle swallows: its centre over the receptacle's footprint and its
// top below the receptacle's top. A world of solid boxes has no mattress under a headboard, no
// sofa seat under a backrest, no open shelf: such a child could never be seen (216 of the 1532
// objects of the 20 houses in ../shared/data, books and remotes on beds and sofas among them).
bool swallowedBy(const OrientedBox& child, const OrientedBox& parent) {
  const bool over = parent.contains(Vec3(child.center.x(), child.center.y(), parent.center.z()));
  return over && child.center.z() + child.half_extents.z() < parent.center.z() + parent.half_extents.z() - 0.005;
}

// Receptacles that close (AI2-THOR's openable ones): what lies in them is out of sight.
bool closesOver(const std::string& type) {
  static const std::set<std::string> kClosed{"Fridge", "Microwave", "Box", "Safe", "Cabinet", "Drawer",
                                             "Laptop", "Toilet", "Kettle"};
  return kClosed.count(type) > 0;
}

// Rest the child on the receptacle's top, where a camera can see it as on the real surface.
void setOnTop(OrientedBox& child, const OrientedBox& parent) {
  child.center.z() = parent.center.z() + parent.half_extents.z() + child.half_extents.z();
}

}  // namespace

bool isProcthorHouse(const json& j) {
  if (!j.is_object() || !j.contains("rooms") || !j["rooms"].is_array() || j["rooms"].empty()) return false;
  return j["rooms"][0].is_object() && j["rooms"][0].contains("floorPolygon");
}

World importProcthorHouse(const std::filesystem::path& house_json, const ImportOptions& opt, ImportReport* report) {
  ImportReport local;
  ImportReport& rep = report ? *report : local;
  rep.format = "procthor";
  const std::string src = house_json.string();
  const json j = readJsonFile(house_json);
  const JsonFields f(src);
  if (!isProcthorHouse(j)) f.fail("rooms", "expected a ProcTHOR house: rooms[] with floorPolygon");
  const AssetDb assets = loadAssetDb(findAssetDb(house_json, opt));

  World w;
  w.name = house_json.stem().string();
  w.source = "procthor:" + house_json.filename().string();
  w.has_floor = true;

  const json& rooms = f.array(j, "", "rooms");
  for (size_t i = 0; i < rooms.size(); ++i) {
    const std::string p = "rooms[" + std::to_string(i) + "]";
    Room r;
    r.name = f.string(rooms[i], p, "id");
    r.id = roomNumber(r.name, f, p + ".id");
    r.type = roomType(f.string(rooms[i], p, "roomType"));
    const json& poly = f.array(rooms[i], p, "floorPolygon");
    if (poly.size() < 3) f.fail(p + ".floorPolygon", "expected at least 3 points");
    for (size_t k = 0; k < poly.size(); ++k)
      r.polygon.push_back(plan(unityPoint(poly[k], f, p + ".floorPolygon[" + std::to_string(k) + "]")));
    importers::makeCounterClockwise(r.polygon);
    if (std::abs(polygonArea(r.polygon)) < 0.05) f.fail(p + ".floorPolygon", "expected a non-degenerate polygon");
    r.floor_z = 0.0;
    r.ceiling_z = 0.0;  // set from the walls below
    w.rooms.push_back(std::move(r));
  }

  // Walls: one group per physical wall; openings are cut into the group's wall.
  std::vector<WallGroup> groups;
  std::map<std::string, size_t> group_of_key;
  std::map<std::string, std::pair<size_t, RawWall>> wall_by_id;
  const json& walls = f.array(j, "", "walls");
  for (size_t i = 0; i < walls.size(); ++i) {
    const std::string p = "walls[" + std::to_string(i) + "]";
    const RawWall raw = readWall(walls[i], f, p);
    const std::string key = wallKey(raw.a, raw.b);
    auto [it, fresh] = group_of_key.emplace(key, groups.size());
    if (fresh) {
      WallGroup g;
      g.wall.a = raw.a;
      g.wall.b = raw.b;
      g.wall.thickness = opt.wall_thickness;
      g.wall.z0 = raw.z0;
      g.wall.z1 = raw.z1;
      groups.push_back(std::move(g));
    }
    WallGroup& g = groups[it->second];
    g.wall.z1 = std::max(g.wall.z1, raw.z1);
    g.rooms.insert(raw.room);
    g.all_empty = g.all_empty && raw.empty;
    wall_by_id[f.string(walls[i], p, "id")] = {it->second, raw};
    for (auto& r : w.rooms)
      if (r.id == raw.room) r.ceiling_z = std::max(r.ceiling_z, raw.z1);
  }
  for (auto& r : w.rooms)
    if (r.ceiling_z <= r.floor_z + 0.5) r.ceiling_z = r.floor_z + 2.5;

  int door_id = 0;
  int closed_exterior = 0;
  const json no_doors = json::array();
  const json& doors = j.contains("doors") ? f.array(j, "", "doors") : no_doors;
  for (size_t i = 0; i < doors.size(); ++i) {
    const std::string p = "doors[" + std::to_string(i) + "]";
    const std::string room0 = f.string(doors[i], p, "room0"), room1 = f.string(doors[i], p, "room1");
    const std::string wall1 = doors[i].contains("wall1") && doors[i]["wall1"].is_string() ? doors[i]["wall1"].get<std::string>() : "";
    // The front door (to the exterior) stays shut: nothing outside the house is modelled.
    if (room0 == room1 || wall1.rfind("wall|exterior", 0) == 0) {
      ++closed_exterior;
      continue;
    }
    const std::string wall0 = f.string(doors[i], p, "wall0");
    auto wit = wall_by_id.find(wall0);
    if (wit == wall_by_id.end()) f.fail(p + ".wall0", "refers to unknown wall \"" + wall0 + "\"");
    const auto& [gi, raw] = wit->second;
    const json& hole = f.array(doors[i], p, "holePolygon");
    if (hole.size() != 2) f.fail(p + ".holePolygon", "expected 2 corners (lower, upper)");
    const Vec3 h0 = unityPoint(hole[0], f, p + ".holePolygon[0]"), h1 = unityPoint(hole[1], f, p + ".holePolygon[1]");
    // Hole x is measured along wall0 from its polygon[0], y is height above the floor.
    const Vec2 p0 = raw.origin + raw.dir * h0.x(), p1 = raw.origin + raw.dir * h1.x();
    Wall& wl = groups[gi].wall;
    const double len = (wl.b - wl.a).norm();
    const Vec2 u = (wl.b - wl.a) / len;
    double s0 = (p0 - wl.a).dot(u), s1 = (p1 - wl.a).dot(u);
    if (s0 > s1) std::swap(s0, s1);
    if (s0 < -0.05 || s1 > len + 0.05)
      rep.warnings.push_back(p + ": door hole runs past its wall's ends; clipped");
    Opening o;
    o.start = std::clamp(s0, 0.0, len);
    o.end = std::clamp(s1, 0.0, len);
    o.bottom = std::min(h0.y(), h1.y());
    o.top = std::max(h0.y(), h1.y());
    if (o.end - o.start < 0.1 || o.top - o.bottom < 0.5) f.fail(p + ".holePolygon", "expected a door-sized hole");
    wl.openings.push_back(o);
    Door d;
    d.id = ++door_id;
    d.room_a = roomNumber(room0, f, p + ".room0");
    d.room_b = roomNumber(room1, f, p + ".room1");
    d.center = wl.a + u * (0.5 * (o.start + o.end));
    d.width = o.end - o.start;
    d.height = o.top - o.bottom;
    w.doors.push_back(d);
  }
  int open_walls = 0;
  for (auto& g : groups) {
    if (!g.all_empty) {
      std::sort(g.wall.openings.begin(), g.wall.openings.end(), [](const Opening& a, const Opening& b) { return a.start < b.start; });
      w.walls.push_back(g.wall);
      continue;
    }
    // A wall marked empty on both sides is an open connection (kitchen to living room).
    if (g.rooms.size() != 2) continue;
    ++open_walls;
    Door d;
    d.id = ++door_id;
    d.room_a = *g.rooms.begin();
    d.room_b = *g.rooms.rbegin();
    d.center = 0.5 * (g.wall.a + g.wall.b);
    d.width = (g.wall.b - g.wall.a).norm();
    d.height = g.wall.z1 - g.wall.z0;
    w.doors.push_back(d);
  }
  if (closed_exterior) rep.notes.push_back(std::to_string(closed_exterior) + " exterior door(s) left closed");
  if (open_walls) rep.notes.push_back(std::to_string(open_walls) + " open wall segment(s) became doorless doors");

  // Objects and their children (small objects placed on receptacles). Each stack entry carries
  // the index in w.objects of its parent and the parent's objectType (-1, "" at the top level).
  struct Entry {
    const json* o;
    std::string path;
    int parent;
    std::string parent_type;
  };
  std::vector<Entry> stack;
  const json no_objects = json::array();
  const json& objects = j.contains("objects") ? f.array(j, "", "objects") : no_objects;
  for (size_t i = objects.size(); i-- > 0;) stack.push_back({&objects[i], "objects[" + std::to_string(i) + "]", -1, ""});
  int lifted = 0, closed_in = 0;
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    const json& o = *e.o;
    const std::string& p = e.path;
    ++rep.source_objects;
    int index = -1;
    const std::string asset = f.string(o, p, "assetId");
    auto a = assets.find(asset);
    if (a == assets.end()) {
      ++rep.skipped_entries;
      rep.warnings.push_back(p + ": asset \"" + asset + "\" not in the asset database; skipped");
    } else {
      const Vec3 pos = unityPoint(f.member(o, p, "position"), f, p + ".position");
      const Vec3 rot = unityPoint(f.member(o, p, "rotation"), f, p + ".rotation");
      if ((a->second.size.array() <= 0).any()) f.fail(p + ".assetId", "asset \"" + asset + "\" has a non-positive size");
      Object obj;
      obj.category = objectCategory(a->second.type);
      obj.box = objectBox(pos, rot, a->second.size);
      if (e.parent >= 0 && swallowedBy(obj.box, w.objects[static_cast<size_t>(e.parent)].box)) {
        if (closesOver(e.parent_type)) {
          ++closed_in;
        } else {
          setOnTop(obj.box, w.objects[static_cast<size_t>(e.parent)].box);
          ++lifted;
        }
      }
      index = static_cast<int>(w.objects.size());
      w.objects.push_back(std::move(obj));
    }
    if (o.contains("children")) {
      const json& ch = f.array(o, p, "children");
      const std::string type = a == assets.end() ? std::string() : a->second.type;
      for (size_t k = ch.size(); k-- > 0;)
        stack.push_back({&ch[k], p + ".children[" + std::to_string(k) + "]", index, type});
    }
  }
  if (lifted)
    rep.notes.push_back(std::to_string(lifted) + " object(s) inside the box of the receptacle they lie on "
                        "(a mattress under a headboard, a sofa seat, a shelf) set on its top");
  if (closed_in) rep.notes.push_back(std::to_string(closed_in) + " object(s) left inside a closed receptacle (fridge, box, ...)");
  importers::assignRoomsAndDropOutside(w, &rep);

  // Start: the agent pose from metadata when it is inside a room and clear of objects.
  bool have_start = false;
  if (j.contains("metadata") && j["metadata"].is_object() && j["metadata"].contains("agent")) {
    const json& ag = j["metadata"]["agent"];
    const Vec3 pos = unityPoint(f.member(ag, "metadata.agent", "position"), f, "metadata.agent.position");
    double yaw_deg = 0;
    if (ag.contains("rotation")) yaw_deg = unityPoint(ag["rotation"], f, "metadata.agent.rotation").y();
    const Room* r = w.roomAt(plan(pos));
    if (r) {
      w.start.position = Vec3(pos.x(), pos.z(), r->floor_z + opt.flight_height);
      // Unity's forward is +z (our +y) turning clockwise with rotation.y.
      w.start.yaw = wrapAngle(kPi / 2 - deg2rad(yaw_deg));
      have_start = importers::clearanceAt(w, w.start.position) >= 0.3;
    }
    if (!have_start) rep.notes.push_back("metadata.agent is not a free point at flight height; start moved");
  }
  if (!have_start) w.start = importers::freeStartInLargestRoom(w, opt.flight_height, src);

  validateWorld(w, src);
  return w;
}

}  // namespace ussnav
