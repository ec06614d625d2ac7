#include "ussnav/sim/importers/gazebo.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_set>

#include "import_util.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

using importers::fmt;

// "aws_robomaker_residential_Bed_01" -> "Bed"; "aws_robomaker_hospital_floor_01_walls" ->
// "floor_01_walls"; "InstrumentCart1" stays.
std::string baseName(const std::string& model) {
  std::string s = model;
  for (const char* family : {"residential_", "hospital_", "retail_", "warehouse_"}) {
    const std::string prefix = std::string("aws_robomaker_") + family;
    if (s.rfind(prefix, 0) == 0) {
      s = s.substr(prefix.size());
      break;
    }
  }
  // Trailing "_01", "_02": model variants.
  while (s.size() > 3 && s[s.size() - 3] == '_' && std::isdigit((unsigned char)s[s.size() - 2]) &&
         std::isdigit((unsigned char)s.back()))
    s.resize(s.size() - 3);
  return s;
}

enum class Kind { kWall, kSlab, kSkip, kObject, kDoor };

struct ModelRule {
  Kind kind = Kind::kObject;
  std::string category;  // kObject
  std::string why;       // kSkip, kSlab: the note
  // Nominal box for models whose geometry is not in the data (Gazebo Fuel): width (model x),
  // depth (model y), height; the model origin is the middle of its bottom face.
  double sx = 0, sy = 0, sz = 0;
};
ModelRule obj(const char* category) { return {Kind::kObject, category, "", 0, 0, 0}; }
ModelRule fuel(const char* category, double sx, double sy, double sz) { return {Kind::kObject, category, "", sx, sy, sz}; }
ModelRule rule(Kind kind, const char* why) { return {kind, "", why, 0, 0, 0}; }

// Categories follow the generator's object table (docs/object-table.md) where one fits. Fuel
// sizes are typical real sizes (no mesh to measure); footprints of objects whose orientation in
// the model frame is unknown are square.
const std::map<std::string, ModelRule>& objectTable() {
  static const std::map<std::string, ModelRule> t{
      // AWS residential, retail, warehouse and hospital models (collision box from objects.tsv).
      {"bed", obj("bed")},
      {"nightstand", obj("nightstand")},
      {"wardrobe", obj("wardrobe")},
      {"chaira", obj("chair")},
      {"chaird", obj("chair")},
      {"coffeetable", obj("coffee table")},
      {"kitchentable", obj("dining table")},
      {"balconytable", obj("table")},
      {"readingdesk", obj("desk")},
      {"sofa", obj("sofa")},
      {"sofab", obj("sofa")},
      {"sofac", obj("sofa")},
      {"tv", obj("tv")},
      {"tvcabinet", obj("tv stand")},
      {"refrigerator", obj("fridge")},
      {"kitchencabinet", obj("kitchen counter")},
      {"cookingbench", obj("stove")},
      {"rangehood", obj("range hood")},
      {"kitchenutensils", obj("kitchen utensils")},
      {"seasoningbox", obj("box")},
      {"tableware", obj("tableware")},
      {"trash", obj("trash can")},
      {"vase", obj("vase")},
      {"ball", obj("ball")},
      {"board", obj("board")},
      {"dumbbell", obj("dumbbell")},
      {"fitnessequipment", obj("exercise machine")},
      {"shoerack", obj("shoe rack")},
      {"carpet", obj("rug")},
      {"roomwindow", obj("window")},
      {"tablet", obj("tablet")},
      {"bookshelfb", obj("bookshelf")},
      {"computer", obj("computer")},
      {"clutteringa", obj("box")},
      {"clutteringc", obj("box")},
      {"nursesstation", obj("reception desk")},
      {"elevator_01_portal", obj("elevator")},
      {"elevator_01_door", obj("elevator")},
      {"elevator_01_car", obj("elevator")},
      {"ramp", obj("ramp")},
      {"hospitalsign", obj("sign")},
      // Gazebo-Fuel models of the hospital: no geometry in the data, nominal boxes.
      {"potatochipchair", fuel("chair", 0.55, 0.55, 0.8)},
      {"whitechipchair", fuel("chair", 0.55, 0.55, 0.8)},
      {"chair", fuel("chair", 0.5, 0.5, 0.9)},
      {"officechairblack", fuel("office chair", 0.65, 0.65, 1.1)},
      // Hospital beds: in the wards they stand inside the bed curtains, long side along x.
      {"cgmclassic", fuel("bed", 2.1, 1.0, 0.9)},
      {"malepatientbed", fuel("bed", 2.1, 1.0, 1.0)},
      {"trolleybed", fuel("stretcher", 2.0, 0.7, 0.9)},
      {"trolleybedpatient", fuel("stretcher", 2.0, 0.7, 1.1)},
      {"toilet", fuel("toilet", 0.6, 0.6, 0.8)},
      {"shower", fuel("shower", 0.9, 0.9, 2.0)},
      {"kitchensink", fuel("sink", 0.8, 0.8, 0.9)},
      {"vendingmachine", fuel("vending machine", 0.9, 0.9, 1.8)},
      {"storagerack", fuel("shelf", 1.0, 1.0, 1.8)},
      {"storagerackcovered", fuel("shelf", 1.0, 1.0, 1.8)},
      {"storagerackcoveropen", fuel("shelf", 1.0, 1.0, 1.8)},
      {"metalcabinet", fuel("cabinet", 0.9, 0.9, 1.8)},
      {"drawer", fuel("cabinet", 0.5, 0.5, 0.7)},
      {"bedsidetable", fuel("nightstand", 0.5, 0.5, 0.8)},
      {"bedtable", fuel("table", 0.8, 0.8, 0.9)},
      {"adjtable", fuel("table", 0.8, 0.8, 0.9)},
      {"bpcart", fuel("cart", 0.5, 0.5, 1.0)},
      {"instrumentcart1", fuel("cart", 0.6, 0.6, 1.0)},
      {"instrumentcart2", fuel("cart", 0.6, 0.6, 1.0)},
      {"surgicaltrolley", fuel("cart", 0.6, 0.6, 1.0)},
      {"surgicaltrolleymed", fuel("cart", 0.6, 0.6, 1.0)},
      {"parkingtrolleymin", fuel("cart", 0.6, 0.6, 1.0)},
      {"parkingtrolleymax", fuel("cart", 0.6, 0.6, 1.0)},
      {"bmwcart", fuel("cart", 0.6, 0.6, 1.0)},
      {"mopcart3", fuel("cart", 0.6, 0.6, 1.0)},
      {"ivstand", fuel("iv stand", 0.5, 0.5, 1.9)},
      {"xraymachine", fuel("x-ray machine", 1.5, 1.5, 2.0)},
      {"anesthesiamachine", fuel("anesthesia machine", 0.8, 0.8, 1.5)},
      {"bloodpressuremonitor", fuel("blood pressure monitor", 0.5, 0.5, 1.4)},
      {"patientwheelchair", fuel("wheelchair", 0.9, 0.9, 1.0)},
      // People (static actors): obstacles a detector sees.
      {"scrubs", fuel("person", 0.5, 0.5, 1.75)},
      {"femalevisitor", fuel("person", 0.5, 0.5, 1.7)},
      {"malevisitoronphone", fuel("person", 0.5, 0.5, 1.75)},
      {"malevisitorsit", fuel("person", 0.6, 0.6, 1.3)},
      {"femalevisitorsit", fuel("person", 0.6, 0.6, 1.3)},
      {"visitorkidsit", fuel("person", 0.5, 0.5, 1.0)},
      {"patientfsit", fuel("person", 0.6, 0.6, 1.3)},
      {"eldermalepatient", fuel("person", 0.6, 0.6, 1.3)},
      {"elderladypatient", fuel("person", 0.6, 0.6, 1.3)},
  };
  return t;
}

ModelRule ruleFor(const std::string& model) {
  const std::string b = lower(baseName(model));
  if (b.find("portrait") != std::string::npos) return obj("picture");
  if (b.find("wall") != std::string::npos) return rule(Kind::kWall, "wall mesh");
  if (b.find("floor") != std::string::npos || b.find("ceiling") != std::string::npos)
    return rule(Kind::kSlab, "floor / ceiling (replaced by slabs)");
  if (b == "door" || b == "foldingdoor") return {Kind::kDoor, "door", "", 0, 0, 0};
  if (b == "handle") return rule(Kind::kSkip, "door handle");
  if (b.find("curtain") != std::string::npos) return rule(Kind::kSkip, "cloth curtain");
  if (b.find("light") != std::string::npos || b == "chandelier" || b == "securitycamera" ||
      b.find("airconditioner") != std::string::npos)
    return rule(Kind::kSkip, "fixture (lights, camera, air conditioner)");
  if (const auto it = objectTable().find(b); it != objectTable().end()) return it->second;
  return rule(Kind::kSkip, "unknown model");
}

Mat3 rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

// The collision meshes of a model: models/<model>/meshes/*collision*.dae (any case).
std::vector<fs::path> collisionMeshes(const fs::path& root, const std::string& model) {
  std::vector<fs::path> out;
  const fs::path dir = root / "models" / model / "meshes";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = lower(e.path().filename().string());
    if (e.is_regular_file() && name.find("collision") != std::string::npos && e.path().extension() != "" &&
        lower(e.path().extension().string()) == ".dae")
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void collectTriangles(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent, const Mat3& R,
                      const Vec3& t, std::vector<std::array<Vec3, 3>>& out) {
  const aiMatrix4x4 m = parent * node->mTransformation;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[i]];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      std::array<Vec3, 3> tri;
      for (int k = 0; k < 3; ++k) {
        const aiVector3D p = m * mesh->mVertices[face.mIndices[k]];
        tri[k] = R * Vec3(p.x, p.y, p.z) + t;
      }
      out.push_back(tri);
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collectTriangles(scene, node->mChildren[c], m, R, t, out);
}

// World-frame triangles of a COLLADA file placed at (R, t). Like Gazebo, `<up_axis>` is ignored;
// `<unit>` is applied.
std::vector<std::array<Vec3, 3>> readCollada(const fs::path& file, const Mat3& R, const Vec3& t) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate);
  if (!scene || !scene->mRootNode)
    throw InputError(file.string(), "", std::string("not a readable COLLADA mesh: ") + importer.GetErrorString());
  std::vector<std::array<Vec3, 3>> out;
  collectTriangles(scene, scene->mRootNode, aiMatrix4x4(), R, t, out);
  if (out.empty()) throw InputError(file.string(), "", "the mesh has no triangles");
  return out;
}

// The dataset folder and its .world file for any accepted path; empty paths when not one.
struct Dataset {
  fs::path root, world, table;
};
Dataset locate(const fs::path& path) {
  std::error_code ec;
  fs::path root;
  if (fs::is_directory(path, ec)) {
    root = path;
  } else if (lower(path.extension().string()) == ".world" || path.filename() == "objects.tsv") {
    root = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  } else {
    return {};
  }
  Dataset d;
  if (!fs::is_regular_file(root / "objects.tsv", ec)) return {};
  if (lower(path.extension().string()) == ".world") {
    d.world = path;
  } else {
    for (const auto& e : fs::directory_iterator(root, ec))
      if (e.is_regular_file() && lower(e.path().extension().string()) == ".world") {
        d.world = e.path();
        break;
      }
  }
  if (d.world.empty()) return {};
  d.root = root;
  d.table = root / "objects.tsv";
  return d;
}

// Separating-axis test of a triangle against an axis-aligned box (centre c, half size h):
// the box's 3 face normals, the triangle's normal and the 9 edge x axis cross products.
bool triangleOverlapsBox(const std::array<Vec3, 3>& tri, const Vec3& c, const Vec3& h) {
  const Vec3 v[3] = {tri[0] - c, tri[1] - c, tri[2] - c};
  const Vec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  auto separated = [&](const Vec3& axis) {
    if (axis.squaredNorm() < 1e-24) return false;  // parallel edges: no axis
    const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
    const double r = h.x() * std::abs(axis.x()) + h.y() * std::abs(axis.y()) + h.z() * std::abs(axis.z());
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separated(Vec3::Unit(i).cross(e[j]))) return false;
  for (int i = 0; i < 3; ++i)
    if (separated(Vec3::Unit(i))) return false;
  return !separated(e[0].cross(e[1]));
}

}  // namespace

bool isGazeboDataset(const fs::path& path) { return !locate(path).root.empty(); }

std::vector<Vec3i> voxeliseTriangles(const std::vector<std::array<Vec3, 3>>& triangles, double res) {
  std::unordered_set<uint64_t> seen;
  std::vector<Vec3i> cells;
  const Vec3 half = Vec3::Constant(0.5 * res);
  for (const auto& t : triangles) {
    if (!t[0].allFinite() || !t[1].allFinite() || !t[2].allFinite()) continue;
    const Vec3 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]) / res, hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]) / res;
    if ((lo.array().abs() >= importers::kVoxelKeyHalf - 1).any() || (hi.array().abs() >= importers::kVoxelKeyHalf - 1).any()) continue;
    const Vec3i k0(int(std::floor(lo.x())), int(std::floor(lo.y())), int(std::floor(lo.z())));
    const Vec3i k1(int(std::floor(hi.x())), int(std::floor(hi.y())), int(std::floor(hi.z())));
    for (int z = k0.z(); z <= k1.z(); ++z)
      for (int y = k0.y(); y <= k1.y(); ++y)
        for (int x = k0.x(); x <= k1.x(); ++x) {
          const Vec3i c(x, y, z);
          if (!triangleOverlapsBox(t, (c.cast<double>() + Vec3::Constant(0.5)) * res, half)) continue;
          if (seen.insert(importers::packVoxelKey(c)).second) cells.push_back(c);
        }
  }
  importers::sortVoxels(cells);
  return cells;
}

World importGazeboWorld(const fs::path& path, const ImportOptions& opt, ImportReport* report) {
  ImportReport local;
  ImportReport& rep = report ? *report : local;
  rep.format = "gazebo";
  const Dataset ds = locate(path);
  if (ds.root.empty())
    throw InputError(path.string(), "", "not a Gazebo dataset: expected a folder with objects.tsv and a .world file");
  const double res = opt.scan_resolution > 0 ? opt.scan_resolution : 0.1;
  if (!(res >= 0.02 && res <= 0.5)) throw InputError(path.string(), "resolution", "expected a voxel size in [0.02, 0.5] m");

  const importers::TsvTable tab =
      importers::readTsv(ds.table, {"instance", "model", "geometry_in_repo", "x", "y", "z", "roll", "pitch", "yaw",
                                    "aabb_min_x", "aabb_min_y", "aabb_min_z", "aabb_max_x", "aabb_max_y", "aabb_max_z"});
  const int c_inst = tab.column("instance"), c_model = tab.column("model"), c_geom = tab.column("geometry_in_repo");
  const int c_pose[6] = {tab.column("x"), tab.column("y"), tab.column("z"), tab.column("roll"), tab.column("pitch"),
                         tab.column("yaw")};
  const int c_lo[3] = {tab.column("aabb_min_x"), tab.column("aabb_min_y"), tab.column("aabb_min_z")};
  const int c_hi[3] = {tab.column("aabb_max_x"), tab.column("aabb_max_y"), tab.column("aabb_max_z")};
  if (tab.rows.empty()) throw InputError(tab.file, "", "no rows; expected one per model instance");

  std::vector<std::array<Vec3, 3>> wall_tris;
  std::map<std::string, int> skipped;  // why -> count
  World w;
  std::vector<Object> doors;  // decided once the footprint is known
  for (size_t r = 0; r < tab.rows.size(); ++r) {
    const std::string where = "line " + std::to_string(tab.lines[r]);
    const std::string& inst = tab.cell(r, c_inst);
    const std::string& model = tab.cell(r, c_model);
    const std::string geom = tab.cell(r, c_geom);
    if (inst.empty() || model.empty()) throw InputError(tab.file, where, "empty instance or model name");
    if (geom != "yes" && geom != "no")
      throw InputError(tab.file, where + ": geometry_in_repo", "expected yes or no, got '" + geom + "'");
    ++rep.source_objects;
    double pose[6];  // read for every row: a truncated row fails here, whatever its model
    for (int k = 0; k < 6; ++k) pose[k] = tab.number(r, c_pose[k]);
    const ModelRule rule = ruleFor(model);
    if (rule.kind == Kind::kSkip || rule.kind == Kind::kSlab) {
      ++skipped[rule.why];
      ++rep.skipped_entries;
      if (rule.why == "unknown model") rep.warnings.push_back(inst + ": unknown model " + model + ", skipped");
      continue;
    }
    if (rule.kind == Kind::kWall) {
      if (geom != "yes") throw InputError(tab.file, where, "wall model " + model + " has no geometry in the data");
      const auto meshes = collisionMeshes(ds.root, model);
      if (meshes.empty())
        throw InputError(tab.file, where, "wall model " + model + ": no *collision*.dae under models/" + model + "/meshes");
      const Mat3 R = rpy(pose[3], pose[4], pose[5]);
      for (const auto& m : meshes) {
        auto tris = readCollada(m, R, Vec3(pose[0], pose[1], pose[2]));
        wall_tris.insert(wall_tris.end(), tris.begin(), tris.end());
      }
      continue;
    }
    Object o;
    o.category = rule.category;
    if (geom == "yes") {
      Vec3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        lo[k] = tab.number(r, c_lo[k]);
        hi[k] = tab.number(r, c_hi[k]);
      }
      if (!lo.allFinite() || !hi.allFinite() || (hi.array() < lo.array()).any())
        throw InputError(tab.file, where + ": aabb", "expected a finite box with min <= max for " + inst);
      o.box.center = 0.5 * (lo + hi);
      o.box.half_extents = (0.5 * (hi - lo)).cwiseMax(Vec3::Constant(0.01));  // wall-thin portals
      o.box.yaw = 0.0;
    } else if (rule.sx > 0) {
      double z0 = pose[2];
      if (!std::isfinite(z0) || std::abs(z0) > 3.0) {
        rep.warnings.push_back(inst + ": pose z = " + tab.cell(r, c_pose[2]) + " m is not on this floor; placed on the floor");
        z0 = 0.0;
      }
      o.box.center = Vec3(pose[0], pose[1], z0 + 0.5 * rule.sz);
      o.box.half_extents = 0.5 * Vec3(rule.sx, rule.sy, rule.sz);
      o.box.yaw = pose[5];
    } else {
      ++skipped["no geometry and no nominal size"];
      ++rep.skipped_entries;
      rep.warnings.push_back(inst + ": model " + model + " has no geometry in the data and no nominal size; skipped");
      continue;
    }
    if (!o.box.center.allFinite() || !o.box.half_extents.allFinite() || !std::isfinite(o.box.yaw))
      throw InputError(tab.file, where, "non-finite pose for " + inst);
    (rule.kind == Kind::kDoor ? doors : w.objects).push_back(o);
  }
  if (wall_tris.empty()) throw InputError(tab.file, "", "no wall model (a model whose name holds 'Wall'); nothing to build");

  // Walls: voxels between the floor (z = 0, Gazebo's ground) and the top of the wall mesh.
  double top = 0.0;
  for (const auto& t : wall_tris)
    for (const auto& p : t) top = std::max(top, p.z());
  const int top_k = int(std::lround(top / res));
  if (top_k < int(std::ceil(opt.flight_height / res)) + 2)
    throw InputError(tab.file, "", "the walls end at z = " + fmt(top) + " m, below flight height; expected walls standing on z = 0");
  std::vector<Vec3i> cells = voxeliseTriangles(wall_tris, res);
  std::erase_if(cells, [&](const Vec3i& c) { return c.z() < 0 || c.z() >= top_k; });
  if (cells.empty()) throw InputError(tab.file, "", "the wall meshes have no part between z = 0 and their top");
  Vec3i lo = cells.front(), hi = cells.front();
  for (const auto& c : cells) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const size_t wall_cells = cells.size();
  for (int j = lo.y(); j <= hi.y(); ++j)
    for (int i = lo.x(); i <= hi.x(); ++i) {
      cells.emplace_back(i, j, -1);    // floor slab, top at z = 0
      cells.emplace_back(i, j, top_k);  // ceiling slab on the walls
    }
  importers::sortVoxels(cells);
  rep.notes.push_back(std::to_string(wall_tris.size()) + " wall triangles -> " + std::to_string(wall_cells) +
                      " voxels of " + fmt(res) + " m up to z = " + fmt(top_k * res) + " m; floor and ceiling slabs over " +
                      fmt((hi.x() - lo.x() + 1) * res, 1) + " x " + fmt((hi.y() - lo.y() + 1) * res, 1) + " m");
  for (const auto& [why, n] : skipped) rep.notes.push_back("skipped " + std::to_string(n) + ": " + why);

  // Doors: the ones on the outline of the building stay shut (nothing outside is modelled);
  // inner doors are left open (removed), as a UAV searching a building would need them.
  const Vec2 fp_lo = lo.head<2>().cast<double>() * res, fp_hi = (hi.head<2>().cast<double>() + Vec2::Ones()) * res;
  int open_doors = 0, shut_doors = 0;
  for (const Object& d : doors) {
    const Vec2 c = d.box.center.head<2>();
    const double edge = std::min((c - fp_lo).minCoeff(), (fp_hi - c).minCoeff());
    if (edge < 0.5) {
      w.objects.push_back(d);
      ++shut_doors;
    } else {
      ++open_doors;
      ++rep.skipped_entries;
    }
  }
  if (!doors.empty())
    rep.notes.push_back("doors: " + std::to_string(open_doors) + " inner left open (removed), " + std::to_string(shut_doors) +
                        " on the outline kept shut");
  // Objects outside the walls' footprint are outside the building.
  std::erase_if(w.objects, [&](const Object& o) {
    const Vec2 c = o.box.center.head<2>();
    const bool out = (c.array() < fp_lo.array()).any() || (c.array() > fp_hi.array()).any();
    if (out) {
      ++rep.dropped_objects;
      rep.warnings.push_back("a " + o.category + " at (" + fmt(c.x()) + ", " + fmt(c.y()) + ") lies outside the walls; dropped");
    }
    return out;
  });
  for (size_t i = 0; i < w.objects.size(); ++i) w.objects[i].id = int(i) + 1;

  // An object mounted on a wall (a TV, a portrait) lies inside the wall's voxels, which round the
  // wall out to the voxel grid: it would be hidden. Voxels whose centre an object's box holds
  // give way to the box (which blocks as much).
  {
    const size_t before = cells.size();
    std::erase_if(cells, [&](const Vec3i& c) {
      if (c.z() < 0 || c.z() >= top_k) return false;
      const Vec3 centre = (c.cast<double>() + Vec3::Constant(0.5)) * res;
      return std::any_of(w.objects.begin(), w.objects.end(), [&](const Object& o) { return o.box.contains(centre); });
    });
    if (cells.size() != before)
      rep.notes.push_back(std::to_string(before - cells.size()) + " wall voxels inside object boxes (wall-mounted TVs, pictures) give way to the boxes");
  }

  // Start: as for scans, with the objects' footprints at flight height blocking too.
  std::vector<Vec3i> blocking(cells.begin(), cells.end());
  const int band_k = int(std::floor(opt.flight_height / res));
  for (const Object& o : w.objects) {
    const Aabb b = o.box.bounds();
    if (b.max.z() < 0.3 || b.min.z() > opt.flight_height + 0.6) continue;
    for (int j = int(std::floor(b.min.y() / res)); j <= int(std::floor(b.max.y() / res)); ++j)
      for (int i = int(std::floor(b.min.x() / res)); i <= int(std::floor(b.max.x() / res)); ++i)
        blocking.emplace_back(i, j, band_k);
  }
  const importers::VoxelStart s = importers::chooseVoxelStart(blocking, res, 0.0, opt.flight_height);
  if (!s.found) throw InputError(tab.file, "", "no free space at flight height inside the walls");
  if (!s.enclosed) rep.warnings.push_back("no free point enclosed by the walls; start placed at the clearest free point");
  w.start.position = Vec3(s.xy.x(), s.xy.y(), opt.flight_height);
  w.start.yaw = 0.0;
  rep.notes.push_back("start (" + fmt(s.xy.x()) + ", " + fmt(s.xy.y()) + ", " + fmt(opt.flight_height) +
                      "), clearance " + fmt(s.clearance) + " m");

  w.name = ds.world.stem().string();
  w.source = "gazebo:" + ds.world.filename().string();
  w.has_floor = false;
  w.obstacles.resolution = res;
  w.obstacles.origin = Vec3::Zero();
  w.obstacles.cells = std::move(cells);
  validateWorld(w, ds.table.string());
  return w;
}

}  // namespace ussnav
