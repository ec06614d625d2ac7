#include "import_util.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"

namespace ussnav::importers {

using nlohmann::json;

namespace {

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t tab = line.find('\t', start);
    out.push_back(line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) break;
    start = tab + 1;
  }
  return out;
}

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

int TsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return int(i);
  throw InputError(file, "header", "missing column '" + name + "'");
}

const std::string& TsvTable::cell(size_t row, int col) const { return rows.at(row).at(size_t(col)); }

double TsvTable::number(size_t row, int col) const {
  const std::string& s = cell(row, col);
  double v = 0;
  const char* end = s.data() + s.size();
  const auto res = std::from_chars(s.data(), end, v);
  if (s.empty() || res.ec != std::errc() || res.ptr != end || !std::isfinite(v))
    throw InputError(file, "line " + std::to_string(lines.at(row)) + ": column '" + header.at(size_t(col)) + "'",
                     "expected a finite number, got '" + s + "'");
  return v;
}

TsvTable readTsv(const std::filesystem::path& path, const std::vector<std::string>& required) {
  TsvTable t;
  t.file = path.string();
  std::istringstream in(readFile(path));
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    auto cells = splitTabs(line);
    if (t.header.empty()) {
      t.header = std::move(cells);
      continue;
    }
    if (cells.size() > t.header.size())
      throw InputError(t.file, "line " + std::to_string(lineno),
                       "expected " + std::to_string(t.header.size()) + " tab-separated columns, got " +
                           std::to_string(cells.size()));
    cells.resize(t.header.size());
    t.rows.push_back(std::move(cells));
    t.lines.push_back(lineno);
  }
  if (t.header.empty()) throw InputError(t.file, "", "empty file; expected a header row and data rows");
  for (const auto& r : required) t.column(r);
  return t;
}

void JsonFields::fail(const std::string& path, const std::string& what) const {
  throw InputError(file_, path, what);
}

const json& JsonFields::member(const json& obj, const std::string& path, const char* key) const {
  if (!obj.is_object()) fail(path, "expected an object");
  auto it = obj.find(key);
  if (it == obj.end()) fail(path.empty() ? key : path + "." + key, "missing required field");
  return *it;
}

const json& JsonFields::array(const json& obj, const std::string& path, const char* key) const {
  const json& j = member(obj, path, key);
  if (!j.is_array()) fail(path.empty() ? key : path + "." + key, "expected an array");
  return j;
}

double JsonFields::number(const json& obj, const std::string& path, const char* key) const {
  const json& j = member(obj, path, key);
  if (!j.is_number() || !std::isfinite(j.get<double>()))
    fail(path.empty() ? key : path + "." + key, "expected a finite number");
  return j.get<double>();
}

std::string JsonFields::string(const json& obj, const std::string& path, const char* key) const {
  const json& j = member(obj, path, key);
  if (!j.is_string()) fail(path.empty() ? key : path + "." + key, "expected a string");
  return j.get<std::string>();
}

std::string categoryFromTypeName(const std::string& type, const std::map<std::string, std::string>& overrides) {
  if (auto it = overrides.find(type); it != overrides.end()) return it->second;
  std::string out;
  for (size_t i = 0; i < type.size(); ++i) {
    const char c = type[i];
    if (c == '_' || c == '-' || c == ' ') {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    const bool upper = std::isupper(static_cast<unsigned char>(c));
    if (upper && i > 0 && !out.empty() && out.back() != ' ') {
      const char prev = type[i - 1];
      const bool next_lower = i + 1 < type.size() && std::islower(static_cast<unsigned char>(type[i + 1]));
      // New word at lower->Upper ("DiningTable") and at the last capital of an acronym ("TVStand").
      if (std::islower(static_cast<unsigned char>(prev)) || std::isdigit(static_cast<unsigned char>(prev)) ||
          (std::isupper(static_cast<unsigned char>(prev)) && next_lower))
        out += ' ';
    }
    out += char(std::tolower(static_cast<unsigned char>(c)));
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

void makeCounterClockwise(std::vector<Vec2>& poly) {
  if (polygonArea(poly) < 0) std::reverse(poly.begin(), poly.end());
}

void assignRoomsAndDropOutside(World& w, ImportReport* report) {
  std::vector<Object> kept;
  kept.reserve(w.objects.size());
  for (auto& o : w.objects) {
    const Room* r = w.roomAt(Vec2(o.box.center.x(), o.box.center.y()));
    if (!r) {
      if (report) {
        ++report->dropped_objects;
        std::ostringstream s;
        s.precision(3);
        s << "dropped object '" << o.category << "' at (" << o.box.center.x() << ", " << o.box.center.y()
          << "): centre outside every room";
        report->warnings.push_back(s.str());
      }
      continue;
    }
    o.room_id = r->id;
    kept.push_back(std::move(o));
  }
  for (size_t i = 0; i < kept.size(); ++i) kept[i].id = int(i) + 1;
  w.objects = std::move(kept);
}

double clearanceAt(const World& w, const Vec3& p) {
  const Vec2 p2(p.x(), p.y());
  double d = std::numeric_limits<double>::infinity();
  for (const auto& wl : w.walls)
    if (p.z() >= wl.z0 && p.z() <= wl.z1) d = std::min(d, segmentDistance(p2, wl.a, wl.b) - 0.5 * wl.thickness);
  for (const auto& o : w.objects) d = std::min(d, o.box.distance(p));
  if (const Room* r = w.roomAt(p2))
    for (size_t i = 0; i < r->polygon.size(); ++i)
      d = std::min(d, segmentDistance(p2, r->polygon[i], r->polygon[(i + 1) % r->polygon.size()]));
  return d;
}

Pose freeStartInLargestRoom(const World& w, double height, const std::string& source) {
  const Room* best = nullptr;
  for (const auto& r : w.rooms)
    if (!best || std::abs(polygonArea(r.polygon)) > std::abs(polygonArea(best->polygon))) best = &r;
  if (!best) throw InputError(source, "rooms", "no room to place the start pose in");
  Vec2 lo = best->polygon.front(), hi = lo;
  for (const auto& p : best->polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double step = 0.1, z = best->floor_z + height;
  Pose pose;
  double best_clear = -1;
  for (double y = lo.y() + 0.5 * step; y < hi.y(); y += step)
    for (double x = lo.x() + 0.5 * step; x < hi.x(); x += step) {
      if (!pointInPolygon(Vec2(x, y), best->polygon)) continue;
      const double c = clearanceAt(w, Vec3(x, y, z));
      if (c > best_clear + 1e-9) {
        best_clear = c;
        pose.position = Vec3(x, y, z);
      }
    }
  if (best_clear < 0) {  // a room thinner than the grid step: its centroid will do
    const Vec2 c = polygonCentroid(best->polygon);
    pose.position = Vec3(c.x(), c.y(), z);
  }
  pose.yaw = 0.0;
  return pose;
}

std::string fmt(double v, int prec) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(prec);
  s << v;
  return s.str();
}

void sortVoxels(std::vector<Vec3i>& cells) {
  std::sort(cells.begin(), cells.end(), [](const Vec3i& a, const Vec3i& b) {
    return std::tie(a.z(), a.y(), a.x()) < std::tie(b.z(), b.y(), b.x());
  });
}

VoxelStart chooseVoxelStart(const std::vector<Vec3i>& cells, double res, double floor_z, double flight) {
  Vec3i lo = cells.front(), hi = lo;
  for (const auto& c : cells) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const int nx = hi.x() - lo.x() + 1, ny = hi.y() - lo.y() + 1;
  std::vector<uint8_t> blocked(size_t(nx) * ny, 0);
  const double band_lo = floor_z + 0.3, band_hi = floor_z + flight + 0.6;
  Vec2 centroid = Vec2::Zero();
  size_t nb = 0;
  for (const auto& c : cells) {
    const double zc = (c.z() + 0.5) * res;
    if (zc < band_lo || zc > band_hi) continue;
    uint8_t& b = blocked[size_t(c.y() - lo.y()) * nx + (c.x() - lo.x())];
    if (!b) {
      b = 1;
      centroid += Vec2(c.x() + 0.5, c.y() + 0.5) * res;
      ++nb;
    }
  }
  VoxelStart out;
  if (nb == 0) return out;
  centroid /= double(nb);
  // Two-pass chamfer distance (in cells) to the nearest blocked cell.
  const double inf = 1e9, d1 = 1.0, d2 = std::sqrt(2.0);
  std::vector<double> dist(blocked.size());
  for (size_t i = 0; i < dist.size(); ++i) dist[i] = blocked[i] ? 0.0 : inf;
  auto at = [&](int x, int y) -> double& { return dist[size_t(y) * nx + x]; };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      double& d = at(x, y);
      if (x > 0) d = std::min(d, at(x - 1, y) + d1);
      if (y > 0) d = std::min(d, at(x, y - 1) + d1);
      if (x > 0 && y > 0) d = std::min(d, at(x - 1, y - 1) + d2);
      if (x + 1 < nx && y > 0) d = std::min(d, at(x + 1, y - 1) + d2);
    }
  for (int y = ny - 1; y >= 0; --y)
    for (int x = nx - 1; x >= 0; --x) {
      double& d = at(x, y);
      if (x + 1 < nx) d = std::min(d, at(x + 1, y) + d1);
      if (y + 1 < ny) d = std::min(d, at(x, y + 1) + d1);
      if (x + 1 < nx && y + 1 < ny) d = std::min(d, at(x + 1, y + 1) + d2);
      if (x > 0 && y + 1 < ny) d = std::min(d, at(x - 1, y + 1) + d2);
    }
  // Enclosed: a blocked cell somewhere left, right, below and above (outside the building fails).
  std::vector<uint8_t> enclosed(blocked.size(), 0);
  std::vector<uint8_t> any_before_x(blocked.size()), any_after_x(blocked.size()), any_before_y(blocked.size()),
      any_after_y(blocked.size());
  for (int y = 0; y < ny; ++y) {
    uint8_t a = 0;
    for (int x = 0; x < nx; ++x) any_before_x[size_t(y) * nx + x] = (a |= blocked[size_t(y) * nx + x]);
    a = 0;
    for (int x = nx - 1; x >= 0; --x) any_after_x[size_t(y) * nx + x] = (a |= blocked[size_t(y) * nx + x]);
  }
  for (int x = 0; x < nx; ++x) {
    uint8_t a = 0;
    for (int y = 0; y < ny; ++y) any_before_y[size_t(y) * nx + x] = (a |= blocked[size_t(y) * nx + x]);
    a = 0;
    for (int y = ny - 1; y >= 0; --y) any_after_y[size_t(y) * nx + x] = (a |= blocked[size_t(y) * nx + x]);
  }
  double best_clear = 0;
  for (size_t i = 0; i < blocked.size(); ++i) {
    enclosed[i] = !blocked[i] && any_before_x[i] && any_after_x[i] && any_before_y[i] && any_after_y[i];
    if (enclosed[i]) best_clear = std::max(best_clear, dist[i]);
  }
  out.enclosed = best_clear > 0;
  if (!out.enclosed)  // no enclosed free cell: take the clearest free cell anywhere
    for (size_t i = 0; i < blocked.size(); ++i) {
      enclosed[i] = !blocked[i];
      if (enclosed[i]) best_clear = std::max(best_clear, dist[i]);
    }
  if (best_clear <= 0) return out;
  const double want = std::min(best_clear, 1.0 / res + 0.5);
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const size_t i = size_t(y) * nx + x;
      if (!enclosed[i] || dist[i] < want) continue;
      const Vec2 p = Vec2(lo.x() + x + 0.5, lo.y() + y + 0.5) * res;
      const double d2c = (p - centroid).squaredNorm();
      if (d2c < best_d2) {
        best_d2 = d2c;
        out.xy = p;
        out.clearance = dist[i] * res - 0.5 * res;
        out.found = true;
      }
    }
  return out;
}

}  // namespace ussnav::importers
