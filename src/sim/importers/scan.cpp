#include "ussnav/sim/importers/scan.hpp"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <unordered_set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/world_io.hpp"
#include "import_util.hpp"

namespace ussnav {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream s(line);
  std::vector<std::string> out;
  for (std::string w; s >> w;) out.push_back(w);
  return out;
}

long toLong(const std::string& s, const std::string& file, const std::string& field) {
  try {
    size_t used = 0;
    const long v = std::stol(s, &used);
    if (used == s.size() && v >= 0) return v;
  } catch (const std::exception&) {
  }
  throw InputError(file, field, "expected a non-negative integer, got '" + s + "'");
}

// ---- OctoMap files: header, then a recursive node stream --------------------------------------

struct OctreeHeader {
  bool binary = false;   // .bt (2 bits per child) vs .ot (float value + child mask per node)
  std::string id;
  size_t size = 0;       // number of nodes the data should hold
  double res = 0.0;
  size_t data_offset = 0;
};

OctreeHeader readOctreeHeader(const std::string& bytes, const std::string& file) {
  OctreeHeader h;
  size_t pos = 0;
  auto nextLine = [&](std::string& line) {
    const size_t nl = bytes.find('\n', pos);
    if (nl == std::string::npos || nl - pos > 1024) return false;
    line = bytes.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = nl + 1;
    return true;
  };
  std::string line;
  if (!nextLine(line)) throw InputError(file, "header", "not an OctoMap file (no header line)");
  if (line.rfind("# Octomap OcTree binary file", 0) == 0)
    h.binary = true;
  else if (line.rfind("# Octomap OcTree file", 0) != 0)
    throw InputError(file, "header", "not an OctoMap file; expected '# Octomap OcTree binary file' (.bt) or "
                                     "'# Octomap OcTree file' (.ot)");
  bool have_res = false, have_size = false;
  while (true) {
    if (!nextLine(line)) throw InputError(file, "header", "ends before the 'data' line (truncated?)");
    const auto w = words(line);
    if (w.empty() || w[0][0] == '#') continue;
    if (w[0] == "data") break;
    if (w.size() != 2) throw InputError(file, "header", "unexpected line '" + line + "'");
    if (w[0] == "id") h.id = w[1];
    else if (w[0] == "size") { h.size = size_t(toLong(w[1], file, "header.size")); have_size = true; }
    else if (w[0] == "res") {
      try { h.res = std::stod(w[1]); } catch (const std::exception&) { h.res = 0; }
      have_res = true;
    }
  }
  if (h.id != "OcTree") throw InputError(file, "header.id", "expected 'OcTree', got '" + h.id + "'");
  if (!have_res || !(h.res > 0.001 && h.res < 10)) throw InputError(file, "header.res", "expected a resolution in (0.001, 10) m");
  if (!have_size) throw InputError(file, "header.size", "missing");
  h.data_offset = pos;
  return h;
}

// Walks the node stream without building anything, so a truncated or corrupt file is reported
// here instead of sending liboctomap past the end of its input. Returns the node count.
size_t walkNodes(const std::string& b, const OctreeHeader& h, const std::string& file) {
  size_t pos = h.data_offset, nodes = 1;
  auto need = [&](size_t n) {
    if (pos + n > b.size())
      throw InputError(file, "data", "file ends inside the octree data (truncated after " + std::to_string(b.size()) + " bytes)");
  };
  // Explicit stack of (depth) for nodes whose record is still to be read, in file order.
  std::vector<int> pending{0};
  while (!pending.empty()) {
    const int depth = pending.back();
    pending.pop_back();
    if (depth > 16) throw InputError(file, "data", "octree deeper than 16 levels (corrupt data)");
    std::vector<int> kids;
    if (h.binary) {
      need(2);
      const unsigned char c[2] = {static_cast<unsigned char>(b[pos]), static_cast<unsigned char>(b[pos + 1])};
      pos += 2;
      for (int i = 0; i < 8; ++i) {
        const int code = (c[i / 4] >> (2 * (i % 4))) & 3;  // 01 free, 10 occupied, 11 inner
        if (code != 0) ++nodes;
        if (code == 3) kids.push_back(depth + 1);
      }
    } else {
      need(5);
      const unsigned char mask = static_cast<unsigned char>(b[pos + 4]);
      pos += 5;
      for (int i = 0; i < 8; ++i)
        if (mask & (1u << i)) {
          ++nodes;
          kids.push_back(depth + 1);
        }
    }
    // Children are read in order 0..7, so push them reversed.
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) pending.push_back(*it);
    if (nodes > h.size + 1) throw InputError(file, "data", "more nodes than the header's size " + std::to_string(h.size));
  }
  if (nodes != h.size)
    throw InputError(file, "data", "holds " + std::to_string(nodes) + " nodes but the header says " + std::to_string(h.size));
  return nodes;
}

// ---- voxels ----------------------------------------------------------------------------------

using importers::kVoxelKeyHalf;
using importers::packVoxelKey;

std::vector<Vec3i> voxelise(const std::vector<Vec3f>& pts, double res, const std::string& file) {
  std::unordered_set<uint64_t> seen;
  seen.reserve(pts.size());
  std::vector<Vec3i> cells;
  for (const auto& p : pts) {
    const Vec3 q = p.cast<double>() / res;
    if ((q.array().abs() >= kVoxelKeyHalf - 1).any())
      throw InputError(file, "points", "a point lies too far from the origin for the voxel grid");
    const Vec3i c(int(std::floor(q.x())), int(std::floor(q.y())), int(std::floor(q.z())));
    if (seen.insert(packVoxelKey(c)).second) cells.push_back(c);
  }
  importers::sortVoxels(cells);
  return cells;
}

// The floor: the top of the densest horizontal layer within 1 m above the lowest occupied
// height (its 0.1th percentile, so stray voxels below do not count), provided it stands out
// as a slab: at least twice as full as any layer 0.15-0.35 m above it. Scans without such a
// layer (floor filtered out, tilted) get the lowest occupied height and *found = false.
double detectFloor(const std::vector<Vec3i>& cells, double res, int* layer_count, bool* found) {
  std::map<int, int> count;
  for (const auto& c : cells) ++count[c.z()];
  const size_t skip = cells.size() / 1000;
  size_t seen = 0;
  int lowest = count.begin()->first;
  for (const auto& [k, n] : count) {
    seen += size_t(n);
    if (seen > skip) {
      lowest = k;
      break;
    }
  }
  const int span = std::max(1, int(std::lround(1.0 / res)));
  int best_k = lowest, best_n = -1;
  for (auto it = count.lower_bound(lowest); it != count.end() && it->first <= lowest + span; ++it)
    if (it->second > best_n) best_k = it->first, best_n = it->second;
  int above = 0;
  for (int d = int(std::ceil(0.15 / res)); d <= int(std::ceil(0.35 / res)); ++d)
    if (auto it = count.find(best_k + d); it != count.end()) above = std::max(above, it->second);
  *found = best_n >= 2 * above;
  *layer_count = *found ? best_n : 0;
  return *found ? (best_k + 1) * res : lowest * res;
}

using importers::fmt;

}  // namespace

std::vector<Vec3f> readPcdXyz(const fs::path& path) {
  const std::string file = path.string();
  const std::string b = readFile(path);
  size_t pos = 0;
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  long points = -1, width = -1, height = 1;
  std::string data;
  while (data.empty()) {
    const size_t nl = b.find('\n', pos);
    if (nl == std::string::npos || nl - pos > 4096)
      throw InputError(file, "header", "no DATA line; expected a PCD v0.7 header (FIELDS ... POINTS ... DATA binary|ascii)");
    std::string line = b.substr(pos, nl - pos);
    pos = nl + 1;
    const auto w = words(line);
    if (w.empty() || w[0][0] == '#') continue;
    const std::string& k = w[0];
    if (k == "FIELDS") fields.assign(w.begin() + 1, w.end());
    else if (k == "SIZE") for (size_t i = 1; i < w.size(); ++i) sizes.push_back(int(toLong(w[i], file, "SIZE")));
    else if (k == "TYPE") for (size_t i = 1; i < w.size(); ++i) types.push_back(w[i][0]);
    else if (k == "COUNT") for (size_t i = 1; i < w.size(); ++i) counts.push_back(int(toLong(w[i], file, "COUNT")));
    else if (k == "POINTS" && w.size() == 2) points = toLong(w[1], file, "POINTS");
    else if (k == "WIDTH" && w.size() == 2) width = toLong(w[1], file, "WIDTH");
    else if (k == "HEIGHT" && w.size() == 2) height = toLong(w[1], file, "HEIGHT");
    else if (k == "DATA") data = w.size() > 1 ? w[1] : "?";
  }
  if (counts.empty()) counts.assign(fields.size(), 1);
  if (fields.empty() || sizes.size() != fields.size() || types.size() != fields.size() || counts.size() != fields.size())
    throw InputError(file, "FIELDS", "expected FIELDS, SIZE, TYPE (and COUNT) with one entry per field");
  if (points < 0) points = width >= 0 ? width * height : -1;
  if (points < 0) throw InputError(file, "POINTS", "missing (and no WIDTH/HEIGHT)");
  // Byte offset of x, y, z within a record.
  int offset[3] = {-1, -1, -1}, column[3] = {-1, -1, -1}, rec = 0, col = 0;
  for (size_t i = 0; i < fields.size(); ++i) {
    for (int a = 0; a < 3; ++a)
      if (fields[i] == std::string(1, char('x' + a))) {
        if (types[i] != 'F' || sizes[i] != 4 || counts[i] != 1)
          throw InputError(file, "FIELDS." + fields[i], "expected a single float32 (SIZE 4, TYPE F, COUNT 1)");
        offset[a] = rec;
        column[a] = col;
      }
    rec += sizes[i] * counts[i];
    col += counts[i];
  }
  if (offset[0] < 0 || offset[1] < 0 || offset[2] < 0) throw InputError(file, "FIELDS", "expected fields x, y and z");
  std::vector<Vec3f> pts;
  pts.reserve(size_t(points));
  auto keep = [&](float x, float y, float z) {
    if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) pts.emplace_back(x, y, z);
  };
  if (data == "binary") {
    const size_t need = size_t(points) * size_t(rec);
    if (b.size() - pos < need)
      throw InputError(file, "POINTS", "header says " + std::to_string(points) + " points (" + std::to_string(need) +
                                           " bytes) but only " + std::to_string(b.size() - pos) +
                                           " bytes follow the header (truncated?)");
    for (long i = 0; i < points; ++i) {
      const char* r = b.data() + pos + size_t(i) * rec;
      float v[3];
      for (int a = 0; a < 3; ++a) std::memcpy(&v[a], r + offset[a], 4);
      keep(v[0], v[1], v[2]);
    }
  } else if (data == "ascii") {
    std::istringstream in(b.substr(pos));
    std::string line;
    for (long i = 0; i < points; ++i) {
      if (!std::getline(in, line))
        throw InputError(file, "POINTS", "header says " + std::to_string(points) + " points but the file holds " +
                                             std::to_string(i) + " (truncated?)");
      const auto w = words(line);
      if (int(w.size()) < col) throw InputError(file, "point " + std::to_string(i), "expected " + std::to_string(col) + " values");
      float v[3];
      for (int a = 0; a < 3; ++a) {
        try { v[a] = std::stof(w[size_t(column[a])]); } catch (const std::exception&) { v[a] = NAN; }
      }
      keep(v[0], v[1], v[2]);
    }
  } else {
    throw InputError(file, "DATA", "unsupported '" + data + "'; expected binary or ascii");
  }
  return pts;
}

OctreeVoxels readOctomapOccupied(const fs::path& path) {
  const std::string file = path.string();
  const std::string bytes = readFile(path);
  const OctreeHeader h = readOctreeHeader(bytes, file);
  walkNodes(bytes, h, file);
  std::istringstream in(bytes);
  std::unique_ptr<octomap::OcTree> tree;
  if (h.binary) {
    tree = std::make_unique<octomap::OcTree>(h.res);
    if (!tree->readBinary(in)) throw InputError(file, "data", "liboctomap could not read the binary octree");
  } else {
    std::unique_ptr<octomap::AbstractOcTree> t(octomap::AbstractOcTree::read(in));
    auto* oc = dynamic_cast<octomap::OcTree*>(t.get());
    if (!oc) throw InputError(file, "data", "liboctomap could not read the octree (expected an OcTree)");
    t.release();
    tree.reset(oc);
  }
  OctreeVoxels out;
  out.resolution = tree->getResolution();
  const double r = out.resolution;
  for (auto it = tree->begin_leafs(), end = tree->end_leafs(); it != end; ++it) {
    if (!tree->isNodeOccupied(*it)) continue;
    const double s = it.getSize();
    const int n = std::max(1, int(std::lround(s / r)));
    const octomap::point3d c = it.getCoordinate();
    const Vec3 lo = Vec3(c.x(), c.y(), c.z()) - Vec3::Constant(0.5 * s);
    for (int a = 0; a < n; ++a)
      for (int bb = 0; bb < n; ++bb)
        for (int k = 0; k < n; ++k)
          out.centers.push_back((lo + Vec3(a + 0.5, bb + 0.5, k + 0.5) * r).cast<float>());
  }
  return out;
}

World importScan(const fs::path& path, const ImportOptions& opt, ImportReport* report) {
  ImportReport local;
  ImportReport& rep = report ? *report : local;
  rep.format = "scan";
  const std::string file = path.string();
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  std::vector<Vec3f> pts;
  double res = opt.scan_resolution;
  if (ext == ".pcd") {
    pts = readPcdXyz(path);
    if (res <= 0) res = 0.1;
  } else if (ext == ".bt" || ext == ".ot") {
    OctreeVoxels v = readOctomapOccupied(path);
    pts = std::move(v.centers);
    if (res <= 0) res = v.resolution;
  } else {
    throw InputError(file, "", "unknown scan format; expected .bt, .ot or .pcd");
  }
  if (!(res >= 0.01 && res <= 1.0)) throw InputError(file, "resolution", "expected a voxel size in [0.01, 1] m");
  if (pts.empty()) throw InputError(file, "", "no occupied points; nothing to build a world from");
  std::vector<Vec3i> cells = voxelise(pts, res, file);

  int floor_cells = 0;
  bool floor_found = false;
  const double floor_z = detectFloor(cells, res, &floor_cells, &floor_found);
  if (!floor_found)
    rep.warnings.push_back("no floor layer in the scan; floor taken at the lowest occupied height, z = " + fmt(floor_z) + " m");
  const double z_lo = floor_z - opt.scan_crop_below, z_hi = floor_z + opt.scan_crop_above;
  const size_t before = cells.size();
  std::erase_if(cells, [&](const Vec3i& c) {
    const double zc = (c.z() + 0.5) * res;
    return zc < z_lo || zc > z_hi;
  });
  rep.notes.push_back("floor at z = " + fmt(floor_z) + " m (" + std::to_string(floor_cells) + " cells); kept z in [" +
                      fmt(z_lo) + ", " + fmt(z_hi) + "], dropped " + std::to_string(before - cells.size()) + " of " +
                      std::to_string(before) + " voxels");
  // A real floor covers much of the footprint; warn when the scan has (almost) none.
  std::unordered_set<uint64_t> columns;
  for (const auto& c : cells) columns.insert(packVoxelKey(Vec3i(c.x(), c.y(), 0)));
  if (floor_found && floor_cells < 0.2 * double(columns.size()))
    rep.warnings.push_back("the scan has little floor (" + std::to_string(floor_cells) + " floor cells under " +
                           std::to_string(columns.size()) + " occupied columns); has_floor=false leaves it open below");

  World w;
  w.name = path.stem().string();
  w.source = "scan:" + path.filename().string();
  w.has_floor = false;
  w.obstacles.resolution = res;
  w.obstacles.origin = Vec3::Zero();
  w.obstacles.cells = std::move(cells);
  if (w.obstacles.cells.empty()) throw InputError(file, "", "no voxels left after cropping to the floor band");

  const importers::VoxelStart s = importers::chooseVoxelStart(w.obstacles.cells, res, floor_z, opt.flight_height);
  if (!s.found) throw InputError(file, "", "no free space at flight height above the detected floor");
  if (!s.enclosed) rep.warnings.push_back("no free point enclosed by the scan; start placed at the clearest free point");
  w.start.position = Vec3(s.xy.x(), s.xy.y(), floor_z + opt.flight_height);
  w.start.yaw = 0.0;
  rep.notes.push_back("start (" + fmt(s.xy.x()) + ", " + fmt(s.xy.y()) + ", " + fmt(w.start.position.z()) +
                      "), clearance " + fmt(s.clearance) + " m in the 2D projection");
  validateWorld(w, file);
  return w;
}

}  // namespace ussnav
