#include "ussnav/sim/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "ussnav/core/error.hpp"

namespace ussnav {

std::vector<Vec3> lawnmowerWaypoints(const GtPlanner& planner, double spacing) {
  const std::vector<Vec2> free = planner.freeSamples(1);
  if (free.empty()) return {};
  Vec2 lo = free.front(), hi = free.front();
  for (const auto& p : free) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::vector<Vec3> out;
  bool forward = true;
  const double step = 0.1;
  for (double y = lo.y() + 0.5 * spacing; y <= hi.y(); y += spacing, forward = !forward) {
    std::vector<Vec3> row;
    bool in_run = false;
    Vec2 run_start;
    for (double x = lo.x(); x <= hi.x() + step; x += step) {
      const bool f = x <= hi.x() && planner.freeAt(Vec2(x, y));
      if (f && !in_run) in_run = true, run_start = Vec2(x, y);
      if (!f && in_run) {
        in_run = false;
        const Vec2 run_end(x - step, y);
        if ((run_end - run_start).norm() >= 0.3) {
          row.emplace_back(run_start.x(), y, planner.flightZ());
          row.emplace_back(run_end.x(), y, planner.flightZ());
        }
      }
    }
    if (!forward) std::reverse(row.begin(), row.end());
    out.insert(out.end(), row.begin(), row.end());
  }
  return out;
}

std::vector<Vec3> spiralWaypoints(const GtPlanner& planner, const Vec2& center, double spacing) {
  const std::vector<Vec2> free = planner.freeSamples(4);
  double rmax = 0;
  for (const auto& p : free) rmax = std::max(rmax, (p - center).norm());
  std::vector<Vec3> out;
  const double a = spacing / (2 * kPi);
  for (double theta = 0.5; a * theta <= rmax;) {
    const double r = a * theta;
    const Vec2 p = center + r * Vec2(std::cos(theta), std::sin(theta));
    if (planner.freeAt(p)) out.emplace_back(p.x(), p.y(), planner.flightZ());
    theta += 1.0 / std::max(r, 0.5);  // ~1 m of arc per point
  }
  return out;
}

std::vector<Vec3> loadWaypointsCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "", "cannot open trajectory file");
  std::vector<Vec3> out;
  std::string line;
  int n = 0;
  std::array<int, 3> col{0, 1, 2};  // columns of x, y, z
  int columns = 3;
  bool header_possible = true;  // only the first row that is not a comment
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    const bool header = header_possible && line.find_first_of("0123456789") != 0 && line[0] != '-' && line[0] != '.';
    header_possible = false;
    if (header) {
      // A header: columns named x, y, z are read wherever they are (t,x,y,z,yaw from `explore`).
      std::array<int, 3> named{-1, -1, -1};
      for (size_t i = 0; i < cells.size(); ++i)
        for (int k = 0; k < 3; ++k)
          if (cells[i] == std::string(1, char('x' + k))) named[size_t(k)] = int(i);
      if (named[0] >= 0 || named[1] >= 0 || named[2] >= 0) {
        for (int k = 0; k < 3; ++k)
          if (named[size_t(k)] < 0)
            throw InputError(path.string(), "line " + std::to_string(n),
                             std::string("header names no '") + char('x' + k) + "' column");
        col = named;
        columns = *std::max_element(col.begin(), col.end()) + 1;
      }
      continue;
    }
    if (int(cells.size()) < columns)
      throw InputError(path.string(), "line " + std::to_string(n),
                       "expected " + std::to_string(columns) + " comma-separated columns with x,y,z");
    double v[3];
    for (int i = 0; i < 3; ++i) {
      const std::string& cell = cells[size_t(col[size_t(i)])];
      try {
        v[i] = std::stod(cell);
      } catch (const std::exception&) {
        throw InputError(path.string(), "line " + std::to_string(n), "'" + cell + "' is not a number");
      }
      if (!std::isfinite(v[i])) throw InputError(path.string(), "line " + std::to_string(n), "non-finite value");
    }
    out.emplace_back(v[0], v[1], v[2]);
  }
  if (out.empty()) throw InputError(path.string(), "", "no waypoints (expected CSV rows x,y,z)");
  return out;
}

std::vector<Vec3> connectWaypoints(const GtPlanner& planner, const Vec3& start,
                                   const std::vector<Vec3>& waypoints, int* skipped) {
  std::vector<Vec3> path{Vec3(start.x(), start.y(), planner.flightZ())};
  int skip = 0;
  for (const auto& w : waypoints) {
    const Vec2 from = path.back().head<2>();
    if ((w.head<2>() - from).norm() < 0.2) continue;
    auto seg = planner.shortestPath(from, Vec2(w.x(), w.y()));
    if (!seg) {
      ++skip;
      continue;
    }
    for (size_t i = 1; i < seg->size(); ++i) path.push_back((*seg)[i]);
  }
  if (skipped) *skipped = skip;
  return path;
}

}  // namespace ussnav
