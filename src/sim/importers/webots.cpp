#include "ussnav/sim/importers/webots.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "import_util.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {

namespace fs = std::filesystem;

namespace {

// Nominal boxes for Webots PROTOs whose size the world file does not give. Sizes are in the
// PROTO's own (ENU) frame: x, y, z up. `base`: the node origin is on the object's bottom face
// (floor-standing furniture); otherwise it is the box centre (wall-mounted or sunk objects).
// `offset`: box centre relative to the origin in the local frame, for PROTOs whose origin is at
// one end. Only Bed was checked against its PROTO mesh; the rest are typical real sizes.
// Categories follow the generator's object table (docs/object-table.md) where one fits.
struct ProtoBox {
  const char* category;
  double sx, sy, sz;
  bool base;
  double ox = 0, oy = 0;
};

const std::map<std::string, ProtoBox>& protoTable() {
  static const std::map<std::string, ProtoBox> t{
      {"Bed", {"bed", 2.0, 1.6, 0.65, true}},
      {"Sofa", {"sofa", 2.0, 0.95, 0.85, true}},
      {"Armchair", {"armchair", 0.9, 0.9, 0.85, true}},
      {"Chair", {"chair", 0.5, 0.5, 0.9, true}},
      {"WoodenChair", {"chair", 0.45, 0.45, 0.9, true}},
      {"RoundTable", {"dining table", 1.2, 1.2, 0.75, true}},
      {"Desk", {"desk", 0.7, 1.2, 0.75, true}},
      // Cabinets stand with their origin on the back face, the body towards local -x (every cabinet
      // in the file has its back on a wall that way).
      {"Cabinet", {"cabinet", 0.45, 0.8, 0.8, true, -0.225, 0.0}},
      {"Fridge", {"fridge", 0.7, 0.7, 1.8, true}},
      {"Oven", {"oven", 0.6, 0.6, 0.6, false}},
      {"HotPlate", {"stove", 0.5, 0.6, 0.05, true}},
      {"Sink", {"sink", 0.45, 0.6, 0.2, true}},
      {"BathroomSink", {"sink", 0.45, 0.6, 0.2, false}},
      {"Toilet", {"toilet", 0.7, 0.45, 0.8, true}},
      {"Bathtube", {"bathtub", 1.7, 0.75, 0.6, true}},
      {"WashingMachine", {"washing machine", 0.6, 0.6, 0.85, false}},
      {"Television", {"tv", 0.1, 1.1, 0.65, false}},
      {"DesktopComputer", {"computer", 0.45, 0.2, 0.45, true}},
      {"Monitor", {"monitor", 0.2, 0.55, 0.4, true}},
      {"Keyboard", {"keyboard", 0.15, 0.45, 0.03, true}},
      {"ComputerMouse", {"mouse", 0.1, 0.06, 0.04, true}},
      {"Laptop", {"laptop", 0.25, 0.35, 0.25, true}},
      {"PottedTree", {"plant", 0.6, 0.6, 1.6, true}},
      {"BunchOfSunFlowers", {"vase", 0.3, 0.3, 0.8, true}},
      {"PortraitPainting", {"painting", 0.05, 0.6, 0.8, false}},
      {"LandscapePainting", {"painting", 0.05, 1.0, 0.6, false}},
      {"Radiator", {"radiator", 0.8, 0.1, 0.6, false}},
      {"Clock", {"clock", 0.05, 0.3, 0.3, false}},
      {"FireExtinguisher", {"fire extinguisher", 0.2, 0.2, 0.6, true}},
      {"OfficeTelephone", {"telephone", 0.2, 0.2, 0.1, true}},
      {"FloorLight", {"lamp", 0.4, 0.4, 1.6, true}},
      {"Book", {"book", 0.2, 0.15, 0.04, true}},
      {"BiscuitBox", {"biscuit box", 0.2, 0.06, 0.25, true}},
      {"CerealBox", {"cereal box", 0.2, 0.07, 0.3, true}},
      {"HoneyJar", {"jar", 0.08, 0.08, 0.12, true}},
      {"JamJar", {"jar", 0.08, 0.08, 0.1, true}},
      {"Carafe", {"carafe", 0.1, 0.1, 0.25, true}},
      {"Plate", {"plate", 0.25, 0.25, 0.02, true}},
      {"Glass", {"glass", 0.07, 0.07, 0.1, true}},
      {"Wineglass", {"wine glass", 0.08, 0.08, 0.2, true}},
      {"Knife", {"knife", 0.2, 0.03, 0.02, true}},
      {"Fork", {"fork", 0.18, 0.03, 0.02, true}},
      {"WoodenSpoon", {"spoon", 0.3, 0.05, 0.02, true}},
      {"WaterBottle", {"bottle", 0.07, 0.07, 0.25, true}},
      {"BeerBottle", {"bottle", 0.07, 0.07, 0.25, true}},
      {"Can", {"can", 0.07, 0.07, 0.12, true}},
      {"FruitBowl", {"bowl", 0.25, 0.25, 0.1, true}},
      {"Apple", {"apple", 0.08, 0.08, 0.08, true}},
      {"Orange", {"orange", 0.08, 0.08, 0.08, true}},
      {"Cookware", {"pan", 0.3, 0.3, 0.15, true}},
      {"Lid", {"lid", 0.25, 0.25, 0.05, true}},
      {"RubberDuck", {"rubber duck", 0.1, 0.1, 0.1, true}},
      {"PaperBoat", {"paper boat", 0.2, 0.1, 0.1, true}},
      {"CardboardBox", {"box", 0.4, 0.3, 0.3, true}},
      {"Barbecue", {"barbecue", 0.6, 1.0, 1.0, true}},
      {"Cypress", {"tree", 0.6, 0.6, 3.0, true}},
      // The flight rises towards local -y (its spot lights climb that way), so the box centre
      // sits half a run from the origin; conservatively solid up to the ceiling.
      {"StraightStairs", {"stairs", 1.2, 2.4, 2.4, true, 0.0, -1.2}},
      // Sizes given in the file (size column); these only name the category.
      {"Table", {"table", 0.8, 1.2, 0.75, true}},
      {"Worktop", {"kitchen counter", 0.7, 0.4, 0.06, false}},
  };
  return t;
}

// Fixtures that are not navigation targets nor obstacles worth a box.
const std::set<std::string> kFixtures{"CeilingLight", "CeilingSpotLight", "WallPlug", "SquareManhole",
                                      "PipeSection", "SolidBox", "Carpet"};
// Scene structure: handled elsewhere or not objects at all.
const std::set<std::string> kStructure{"Group", "Solid", "Transform", "Wall", "Door", "Window", "TiagoIron"};

struct Rect {
  double x0, x1, y0, y1;
  std::string name, type;
  bool split_part = false;
  double area() const { return (x1 - x0) * (y1 - y0); }
  bool contains(const Vec2& p) const { return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1; }
};

// A wall-like box (Wall, Window, Door) seen from above: centre line along u.
struct Seg {
  enum Kind { kWall, kWindow, kDoor } kind = kWall;
  std::string name;
  Vec2 c = Vec2::Zero(), u = Vec2::UnitX();
  double half_len = 0, half_thick = 0, z0 = 0, z1 = 0;
  bool tall() const { return z1 - z0 >= 1.5; }
  Vec2 normal() const { return {-u.y(), u.x()}; }
  bool blocks(const Vec2& p, double grow_thick, double grow_len) const {
    const Vec2 d = p - c;
    return std::abs(d.dot(u)) <= half_len + grow_len && std::abs(d.dot(normal())) <= half_thick + grow_thick;
  }
};

bool blocked(const std::vector<Seg>& segs, const Vec2& p, double grow_thick, double grow_len) {
  return std::any_of(segs.begin(), segs.end(),
                     [&](const Seg& s) { return s.tall() && s.blocks(p, grow_thick, grow_len); });
}

std::string patchType(const std::string& def) {
  if (def.rfind("LIVING_ROOM", 0) == 0) return "living room";
  if (def.rfind("KITCHEN", 0) == 0) return "kitchen";
  if (def.rfind("CORRIDOR", 0) == 0) return "corridor";
  if (def.rfind("BATHROOM", 0) == 0) return "bathroom";
  if (def.rfind("ROOM_", 0) == 0) return "bedroom";  // ROOM_1, ROOM_2 hold the beds
  if (def.rfind("GARDEN", 0) == 0) return "garden";
  std::string t = def;
  while (!t.empty() && (std::isdigit(static_cast<unsigned char>(t.back())) || t.back() == '_')) t.pop_back();
  return importers::categoryFromTypeName(t);
}

// Splits overlapping patches at the middle of the overlap, across its thinner direction.
void separateOverlaps(std::vector<Rect>& rs, ImportReport& rep) {
  for (size_t i = 0; i < rs.size(); ++i)
    for (size_t j = i + 1; j < rs.size(); ++j) {
      Rect &a = rs[i], &b = rs[j];
      const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
      const double oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
      if (ox <= 1e-9 || oy <= 1e-9) continue;
      std::ostringstream s;
      s.precision(3);
      s << a.name << " and " << b.name << " overlapped by " << std::min(ox, oy) << " m; split evenly";
      rep.notes.push_back(s.str());
      if (ox < oy) {
        const double mid = 0.5 * (std::max(a.x0, b.x0) + std::min(a.x1, b.x1));
        Rect& left = (a.x0 + a.x1 < b.x0 + b.x1) ? a : b;
        Rect& right = (&left == &a) ? b : a;
        left.x1 = mid;
        right.x0 = mid;
      } else {
        const double mid = 0.5 * (std::max(a.y0, b.y0) + std::min(a.y1, b.y1));
        Rect& low = (a.y0 + a.y1 < b.y0 + b.y1) ? a : b;
        Rect& high = (&low == &a) ? b : a;
        low.y1 = mid;
        high.y0 = mid;
      }
    }
}

// Cuts a patch in two where a chain of tall walls/doors crosses it completely (a patch that
// spans two walled-off spaces). The larger part keeps the name; the other gets a compass suffix.
std::vector<Rect> splitByCrossingWalls(std::vector<Rect> pending, const std::vector<Seg>& segs, ImportReport& rep) {
  std::vector<Rect> done;
  const double step = 0.05, grow = 0.2, margin = 0.5;
  while (!pending.empty()) {
    Rect r = pending.back();
    pending.pop_back();
    bool cut = false;
    for (const auto& s : segs) {
      if (!s.tall()) continue;
      const bool along_x = std::abs(s.u.x()) > 0.9999, along_y = std::abs(s.u.y()) > 0.9999;
      if (!along_x && !along_y) continue;
      const double c = along_x ? s.c.y() : s.c.x();
      const double lo = along_x ? r.y0 : r.x0, hi = along_x ? r.y1 : r.x1;
      if (c < lo + margin || c > hi - margin) continue;
      const double t0 = along_x ? r.x0 : r.y0, t1 = along_x ? r.x1 : r.y1;
      bool full = true;
      for (double t = t0 + 0.5 * step; t < t1 && full; t += step)
        full = blocked(segs, along_x ? Vec2(t, c) : Vec2(c, t), grow, grow);
      if (!full) continue;
      Rect p = r, q = r;
      if (along_x) p.y1 = q.y0 = c; else p.x1 = q.x0 = c;
      const bool p_big = p.area() >= q.area();
      Rect& small = p_big ? q : p;
      small.name = r.name + (along_x ? (p_big ? "_N" : "_S") : (p_big ? "_E" : "_W"));
      small.split_part = true;
      rep.notes.push_back(r.name + " is crossed by wall '" + s.name + "'; split off " + small.name);
      pending.push_back(p);
      pending.push_back(q);
      cut = true;
      break;
    }
    if (!cut) done.push_back(r);
  }
  std::sort(done.begin(), done.end(), [](const Rect& a, const Rect& b) { return a.name < b.name; });
  return done;
}

int rectAt(const std::vector<Rect>& rs, const Vec2& p) {
  for (size_t i = 0; i < rs.size(); ++i)
    if (rs[i].contains(p)) return int(i);
  return -1;
}

Vec3 sizeColumn(const importers::TsvTable& t, size_t row, int col) {
  std::istringstream s(t.cell(row, col));
  Vec3 v;
  if (!(s >> v.x() >> v.y() >> v.z()) || (v.array() <= 0).any())
    throw InputError(t.file, "line " + std::to_string(t.lines[row]) + ": column '" + t.header[size_t(col)] + "'",
                     "expected three positive sizes 'x y z'");
  return v;
}

}  // namespace

World importWebotsApartment(const fs::path& path, const ImportOptions& opt, ImportReport* report) {
  ImportReport local;
  ImportReport& rep = report ? *report : local;
  rep.format = "webots";
  const fs::path dir = fs::is_directory(path) ? path : (path.has_parent_path() ? path.parent_path() : fs::path("."));
  const fs::path rooms_tsv = dir / "rooms_enu.tsv", objects_tsv = dir / "objects_enu.tsv";
  for (const auto& p : {rooms_tsv, objects_tsv})
    if (!fs::exists(p))
      throw InputError(path.string(), "", "expected " + p.filename().string() +
                                              " in the same folder (the derived ENU tables; the .wbt itself is not parsed)");

  const auto rt = importers::readTsv(rooms_tsv, {"room_def", "x_min", "x_max", "y_min", "y_max"});
  std::vector<Rect> rects;
  for (size_t r = 0; r < rt.rows.size(); ++r) {
    Rect q{rt.number(r, rt.column("x_min")), rt.number(r, rt.column("x_max")), rt.number(r, rt.column("y_min")),
           rt.number(r, rt.column("y_max")), rt.cell(r, rt.column("room_def")), "", false};
    q.type = patchType(q.name);
    if (q.x1 - q.x0 < 0.3 || q.y1 - q.y0 < 0.3)
      throw InputError(rt.file, "line " + std::to_string(rt.lines[r]), "expected a patch at least 0.3 m wide");
    // The garden strip is outdoors, behind windows only: not reachable, so not a room.
    if (q.type == "garden") {
      rep.notes.push_back("outdoor patch " + q.name + " dropped (reachable only through windows)");
      continue;
    }
    rects.push_back(q);
  }
  if (rects.empty()) throw InputError(rt.file, "", "no indoor room patches");

  const auto ot = importers::readTsv(objects_tsv, {"node_type", "def", "name", "x_enu", "y_enu", "z_enu",
                                                   "yaw_enu_rad", "size_enu_or_plane"});
  const int c_type = ot.column("node_type"), c_def = ot.column("def"), c_name = ot.column("name");
  const int c_x = ot.column("x_enu"), c_y = ot.column("y_enu"), c_z = ot.column("z_enu");
  const int c_yaw = ot.column("yaw_enu_rad"), c_size = ot.column("size_enu_or_plane");
  std::vector<Seg> segs;
  World w;
  std::optional<Pose> robot;
  std::set<std::string> unknown;
  for (size_t r = 0; r < ot.rows.size(); ++r) {
    const std::string& type = ot.cell(r, c_type);
    const Vec3 pos(ot.number(r, c_x), ot.number(r, c_y), ot.number(r, c_z));
    const double yaw = ot.number(r, c_yaw);
    const std::string label = ot.cell(r, c_name).empty() ? (ot.cell(r, c_def).empty() ? type : ot.cell(r, c_def)) : ot.cell(r, c_name);
    if (type == "Wall" || type == "Window" || type == "Door") {
      const Vec3 size = sizeColumn(ot, r, c_size);
      Seg s;
      s.kind = type == "Wall" ? Seg::kWall : type == "Window" ? Seg::kWindow : Seg::kDoor;
      s.name = label;
      s.c = pos.head<2>();
      const Vec2 ux(std::cos(yaw), std::sin(yaw)), uy(-std::sin(yaw), std::cos(yaw));
      // The length runs along the longer horizontal side (local y for every wall in the file).
      s.u = size.y() >= size.x() ? uy : ux;
      s.half_len = 0.5 * std::max(size.x(), size.y());
      s.half_thick = 0.5 * std::min(size.x(), size.y());
      s.z0 = pos.z();
      s.z1 = pos.z() + size.z();
      segs.push_back(s);
      continue;
    }
    if (type == "TiagoIron") robot = Pose{Vec3(pos.x(), pos.y(), 0.0), yaw};
    if (kStructure.count(type)) continue;
    if (kFixtures.count(type)) {
      ++rep.skipped_entries;
      continue;
    }
    ++rep.source_objects;
    auto it = protoTable().find(type);
    if (it == protoTable().end()) {
      unknown.insert(type);
      ++rep.skipped_entries;
      continue;
    }
    const ProtoBox& pb = it->second;
    Vec3 size(pb.sx, pb.sy, pb.sz);
    if (!ot.cell(r, c_size).empty()) size = sizeColumn(ot, r, c_size);
    Object o;
    o.category = pb.category;
    if (type == "Table") {  // named by shape: low and wide = coffee, small = side, else dining
      const double foot = size.x() * size.y();
      o.category = foot < 0.25 ? "side table" : (size.z() < 0.6 ? "coffee table" : "dining table");
    }
    if (type == "FloorLight" && pos.z() > 0.05) {  // the same PROTO stands on bedside tables
      o.category = "desk lamp";
      size = Vec3(0.25, 0.25, 0.5);
    }
    const Vec2 off = Eigen::Rotation2Dd(yaw) * Vec2(pb.ox, pb.oy);
    o.box.center = Vec3(pos.x() + off.x(), pos.y() + off.y(), pb.base ? pos.z() + 0.5 * size.z() : pos.z());
    o.box.half_extents = 0.5 * size;
    o.box.yaw = wrapAngle(yaw);
    const bool dup = std::any_of(w.objects.begin(), w.objects.end(), [&](const Object& e) {
      return e.category == o.category && (e.box.center - o.box.center).norm() < 0.01;
    });
    if (dup) {
      rep.notes.push_back("duplicate node '" + label + "' (same type and pose as another) ignored");
      continue;
    }
    w.objects.push_back(std::move(o));
  }
  for (const auto& u : unknown) rep.warnings.push_back("PROTO type '" + u + "' has no nominal size; skipped");

  separateOverlaps(rects, rep);
  rects = splitByCrossingWalls(std::move(rects), segs, rep);
  // A split-off part inherits the patch label; fix it where its content says otherwise.
  for (auto& r : rects) {
    if (!r.split_part) continue;
    auto holds = [&](const char* cat) {
      return std::any_of(w.objects.begin(), w.objects.end(), [&](const Object& o) {
        return o.category == cat && r.contains(o.box.center.head<2>());
      });
    };
    const std::string before = r.type;
    if (holds("toilet")) r.type = "bathroom";
    else if (holds("stairs")) r.type = "stairwell";
    if (r.type != before) rep.notes.push_back(r.name + " relabelled " + before + " -> " + r.type + " by its content");
  }

  double ceiling = 0;
  for (const auto& s : segs)
    if (s.tall()) ceiling = std::max(ceiling, s.z1);
  if (ceiling <= 0.5) ceiling = 2.4;
  for (size_t i = 0; i < rects.size(); ++i) {
    const Rect& q = rects[i];
    Room room;
    room.id = int(i) + 1;
    room.name = q.name;
    room.type = q.type;
    room.polygon = {{q.x0, q.y0}, {q.x1, q.y0}, {q.x1, q.y1}, {q.x0, q.y1}};
    room.ceiling_z = ceiling;
    w.rooms.push_back(room);
  }

  // Walls; Door nodes become walls with an opening where rooms lie on both sides.
  int exterior_doors = 0;
  for (const auto& s : segs) {
    Wall wl;
    wl.a = s.c - s.u * s.half_len;
    wl.b = s.c + s.u * s.half_len;
    wl.thickness = 2 * s.half_thick;
    wl.z0 = s.z0;
    wl.z1 = s.z1;
    if (s.kind == Seg::kDoor) {
      const Vec2 probe = s.normal() * (s.half_thick + 0.3);
      const int ra = rectAt(rects, s.c + probe), rb = rectAt(rects, s.c - probe);
      if (ra < 0 || rb < 0 || ra == rb) {
        ++exterior_doors;  // leads outside: kept shut, nothing outside is modelled
      } else {
        // Door PROTO: 0.05 m frame each side, frame 2.0 m high with a 0.05 m top bar.
        Opening o{0.05, 2 * s.half_len - 0.05, 0.0, std::min(1.95, s.z1 - s.z0)};
        wl.openings.push_back(o);
        Door d;
        d.id = int(w.doors.size()) + 1;
        d.room_a = ra + 1;
        d.room_b = rb + 1;
        d.center = s.c;
        d.width = o.end - o.start;
        d.height = o.top - o.bottom;
        w.doors.push_back(d);
      }
    }
    w.walls.push_back(wl);
  }
  if (exterior_doors) rep.notes.push_back(std::to_string(exterior_doors) + " exterior door(s) left closed");

  // Open boundaries: where two rooms touch and no tall wall covers the shared edge.
  const double step = 0.05, touch = 0.1;
  int open_links = 0;
  for (size_t i = 0; i < rects.size(); ++i)
    for (size_t j = i + 1; j < rects.size(); ++j) {
      const Rect &a = rects[i], &b = rects[j];
      for (int axis = 0; axis < 2; ++axis) {  // 0: shared edge is vertical (x = const)
        const double a_lo = axis == 0 ? a.x0 : a.y0, a_hi = axis == 0 ? a.x1 : a.y1;
        const double b_lo = axis == 0 ? b.x0 : b.y0, b_hi = axis == 0 ? b.x1 : b.y1;
        double line;
        if (std::abs(b_lo - a_hi) <= touch) line = 0.5 * (b_lo + a_hi);
        else if (std::abs(a_lo - b_hi) <= touch) line = 0.5 * (a_lo + b_hi);
        else continue;
        const double t0 = std::max(axis == 0 ? a.y0 : a.x0, axis == 0 ? b.y0 : b.x0);
        const double t1 = std::min(axis == 0 ? a.y1 : a.x1, axis == 0 ? b.y1 : b.x1);
        if (t1 - t0 < 0.3) continue;
        double run_start = 0;
        int run = 0;
        auto close = [&]() {
          if (run * step >= 0.5) {
            const double mid = run_start + 0.5 * run * step;
            Door d;
            d.id = int(w.doors.size()) + 1;
            d.room_a = int(i) + 1;
            d.room_b = int(j) + 1;
            d.center = axis == 0 ? Vec2(line, mid) : Vec2(mid, line);
            d.width = run * step;
            d.height = ceiling;
            w.doors.push_back(d);
            ++open_links;
          }
          run = 0;
        };
        for (double t = t0; t + step <= t1 + 1e-9; t += step) {
          const double tc = t + 0.5 * step;
          const Vec2 p = axis == 0 ? Vec2(line, tc) : Vec2(tc, line);
          if (blocked(segs, p, 0.2, 0.0)) {
            close();
          } else {
            if (run == 0) run_start = t;
            ++run;
          }
        }
        close();
      }
    }
  if (open_links) rep.notes.push_back(std::to_string(open_links) + " open passage(s) between rooms became doorless doors");

  importers::assignRoomsAndDropOutside(w, &rep);
  w.name = "webots_complete_apartment";
  w.source = "webots:" + dir.filename().string();
  w.has_floor = true;
  bool have_start = false;
  if (robot && w.roomAt(robot->position.head<2>())) {
    w.start = *robot;
    w.start.position.z() = opt.flight_height;
    have_start = importers::clearanceAt(w, w.start.position) >= 0.3;
  }
  if (!have_start) {
    rep.notes.push_back("robot pose not usable as start; start placed in the largest room");
    w.start = importers::freeStartInLargestRoom(w, opt.flight_height, path.string());
  }
  validateWorld(w, path.string());
  return w;
}

}  // namespace ussnav
