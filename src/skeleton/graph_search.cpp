#include "ussnav/skeleton/graph_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "ussnav/core/error.hpp"

#include "ussnav/skeleton/grid_path.hpp"

namespace ussnav {

namespace {

// Whether the segment from p to the node's centre misses every obstacle voxel recorded inside
// the node's hull (slab test against each voxel cube).
bool segmentAvoidsObstacles(const ScgNode& n, const Vec3& p, double res) {
  if (n.obstacles_overflow) return false;
  const Vec3 d = n.center - p;
  const double h = 0.5 * res;
  for (const Vec3& c : n.obstacles) {
    double t0 = 0.0, t1 = 1.0;
    bool hit = true;
    for (int a = 0; a < 3 && hit; ++a) {
      const double lo = c[a] - h - p[a], hi = c[a] + h - p[a];
      if (std::abs(d[a]) < 1e-12) {
        hit = lo <= 0.0 && hi >= 0.0;
      } else {
        double ta = lo / d[a], tb = hi / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        hit = t0 <= t1;
      }
    }
    if (hit) return false;
  }
  return true;
}

// Nodes that `p` can reach by a straight segment: first those in known free space, else those
// only unobserved space separates (outside the window, say). Nearest first.
std::vector<int> attachNodes(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& p,
                             const PathSearchOptions& opt) {
  const double r = opt.attach_radius > 0 ? opt.attach_radius : 2.0 * g.config().visibility_radius;
  std::vector<int> near = g.nodesWithin(p, r);
  if (near.empty()) {
    const int n = g.nearestNode(p);
    if (n >= 0) near.push_back(n);
  }
  // 1. Polyhedra that contain p: the segment to the centre stays inside convex free space,
  //    which holds wherever the map window has moved on.
  std::vector<int> inside;
  for (int id : near)
    if (g.node(id).polyhedron.contains(p) && segmentAvoidsObstacles(g.node(id), p, map.resolution()))
      inside.push_back(id);
  if (!inside.empty()) return inside;
  if (int(near.size()) > opt.attach_candidates) near.resize(size_t(opt.attach_candidates));
  // 2. Line of sight through known free space.
  std::vector<int> out;
  for (int id : near)
    if (tubeOfSight(map, p, g.node(id).center, g.config().edge_clearance, true)) out.push_back(id);
  if (!out.empty()) return out;
  // 3. Where the map knows nothing (outside the window, say): a straight segment that runs at
  //    most unknown_attach_max outside the node's polyhedron — the rest lies in the convex free
  //    space it covers — and meets no obstacle the map still holds.
  for (int id : near) {
    const ScgNode& n = g.node(id);
    const Vec3 d = p - n.center;
    const double len = d.norm();
    if (len < 1e-9) return {id};
    const Vec3 u = d / len;
    double t_exit = len;
    for (size_t f = 0; f < n.polyhedron.faces.size(); ++f) {
      const double un = n.polyhedron.normals[f].dot(u);
      if (un > 1e-12) t_exit = std::min(t_exit, -(n.polyhedron.normals[f].dot(n.center) + n.polyhedron.offsets[f]) / un);
    }
    if (len - std::max(0.0, t_exit) <= opt.unknown_attach_max && segmentAvoidsObstacles(n, p, map.resolution()) &&
        tubeOfSight(map, p, n.center, g.config().edge_clearance, false))
      out.push_back(id);
  }
  return out;
}

}  // namespace

GraphPath findGraphPath(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& start,
                        const Vec3& goal, const PathSearchOptions& opt) {
  GraphPath result;
  if (!start.allFinite() || !goal.allFinite())
    throw InputError("", "start/goal", "expected finite path end points");
  const double clearance = g.config().edge_clearance;
  if (tubeOfSight(map, start, goal, clearance, true)) {
    result.found = true;
    result.points = {start, goal};
    result.length = (goal - start).norm();
    return result;
  }
  const std::vector<int> from = attachNodes(g, map, start, opt);
  const std::vector<int> to = attachNodes(g, map, goal, opt);
  if (from.empty() || to.empty()) return result;

  const int n = int(g.size());
  const int goal_id = n;  // virtual node
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(size_t(n) + 1, kInf);
  std::vector<int> prev(size_t(n) + 1, -1);  // previous node (-2: the start point)
  std::vector<char> closed(size_t(n) + 1, 0);
  std::vector<double> goal_cost(size_t(n), kInf);
  for (int id : to) goal_cost[size_t(id)] = (goal - g.node(id).center).norm();
  std::vector<signed char> edge_ok(g.edges().size(), -1);  // lazily re-checked against the map

  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  auto h = [&](int id) { return id == goal_id ? 0.0 : (goal - g.node(id).center).norm(); };
  for (int id : from) {
    const double c = (g.node(id).center - start).norm();
    if (c < cost[size_t(id)]) {
      cost[size_t(id)] = c;
      prev[size_t(id)] = -2;
      open.push({c + h(id), id});
    }
  }
  while (!open.empty()) {
    const auto [f, u] = open.top();
    open.pop();
    if (closed[size_t(u)]) continue;
    closed[size_t(u)] = 1;
    if (u == goal_id) break;
    auto relax = [&](int v, double c) {
      if (c < cost[size_t(v)]) {
        cost[size_t(v)] = c;
        prev[size_t(v)] = u;
        open.push({c + h(v), v});
      }
    };
    if (goal_cost[size_t(u)] < kInf) relax(goal_id, cost[size_t(u)] + goal_cost[size_t(u)]);
    for (int e : g.node(u).edges) {
      const ScgEdge& ed = g.edges()[size_t(e)];
      const int v = ed.a == u ? ed.b : ed.a;
      if (closed[size_t(v)] || ed.blocked) continue;
      if (edge_ok[size_t(e)] < 0) {
        const std::vector<Vec3> poly = g.edgePolyline(e);
        edge_ok[size_t(e)] =
            polylineClear(map, poly, false, clearance) && !polylinePassesNear(poly, opt.avoid, opt.avoid_radius) ? 1 : 0;
      }
      if (!edge_ok[size_t(e)]) continue;
      relax(v, cost[size_t(u)] + ed.length);
    }
  }
  if (!closed[size_t(goal_id)]) return result;

  // Walk back: goal <- last node <- ... <- first node <- start, expanding edge waypoints.
  std::vector<int> chain;
  for (int v = prev[size_t(goal_id)]; v >= 0; v = prev[size_t(v)]) chain.push_back(v);
  std::reverse(chain.begin(), chain.end());
  std::vector<Vec3> pts{start, g.node(chain.front()).center};
  for (size_t i = 1; i < chain.size(); ++i) {
    const int e = g.edgeBetween(chain[i - 1], chain[i]);
    std::vector<Vec3> poly = g.edgePolyline(e);
    if (g.edges()[size_t(e)].a != chain[i - 1]) std::reverse(poly.begin(), poly.end());
    pts.insert(pts.end(), poly.begin() + 1, poly.end());
  }
  pts.push_back(goal);
  // Drop repeated points (start or goal on a node centre).
  pts.erase(std::unique(pts.begin(), pts.end(), [](const Vec3& a, const Vec3& b) { return (a - b).norm() < 1e-9; }),
            pts.end());
  if (opt.shortcut) pts = shortcutPolyline(map, pts, true, clearance);
  result.found = true;
  result.nodes = std::move(chain);
  result.length = polylineLength(pts);
  result.points = std::move(pts);
  return result;
}

}  // namespace ussnav
