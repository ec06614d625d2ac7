#include "ussnav/skeleton/expansion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

namespace {

// Unknown voxels a seed's clearance ball may hold before the seed waits for observation:
// the voxels of one gap of max_unknown_gap.
int toleratedUnknownVoxels(const OccupancyMap& map, const SkeletonConfig& cfg) {
  return int(std::floor(cfg.max_unknown_gap / map.resolution() + 1e-9));
}

}  // namespace

RayHit castRayThroughGaps(const OccupancyMap& map, const Vec3& from, const Vec3& to,
                          bool unknown_blocks, double max_gap) {
  RayHit hit;
  const double res = map.resolution();
  const Vec3 d = to - from;
  const double len = d.norm();
  hit.point = to;
  hit.distance = len;
  if (len < 1e-12) return hit;
  const Vec3 dir = d / len;
  Vec3i key = map.keyOf(from);
  const Vec3i end = map.keyOf(to);
  Vec3i step;
  Vec3 t_max, t_delta;
  for (int i = 0; i < 3; ++i) {
    if (dir[i] > 0) {
      step[i] = 1;
      t_max[i] = ((key[i] + 1) * res - from[i]) / dir[i];
      t_delta[i] = res / dir[i];
    } else if (dir[i] < 0) {
      step[i] = -1;
      t_max[i] = (key[i] * res - from[i]) / dir[i];
      t_delta[i] = -res / dir[i];
    } else {
      step[i] = 0;
      t_max[i] = std::numeric_limits<double>::infinity();
      t_delta[i] = std::numeric_limits<double>::infinity();
    }
  }
  auto stopAt = [&](double t, VoxelState st) {
    hit.blocked = true;
    hit.hit_state = st;
    hit.distance = t;
    hit.point = from + dir * t;
    return hit;
  };
  bool in_gap = false;
  double gap_start = 0.0;
  const int max_steps = int(std::ceil(len / res)) * 3 + 3;
  for (int s = 0; s < max_steps && key != end; ++s) {
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    const double t = t_max[axis];
    if (t > len) break;
    key[axis] += step[axis];
    t_max[axis] += t_delta[axis];
    if (!map.inWindow(key)) return stopAt(in_gap ? gap_start : t, VoxelState::Unknown);
    const VoxelState st = map.state(key);
    if (st == VoxelState::Occupied) return stopAt(t, VoxelState::Occupied);
    if (st == VoxelState::Free) {
      in_gap = false;
      continue;
    }
    if (!unknown_blocks) continue;
    if (!in_gap) {
      in_gap = true;
      gap_start = t;
    }
    const double t_exit = std::min({t_max[0], t_max[1], t_max[2]});
    if (t_exit - gap_start > max_gap + 1e-9) return stopAt(gap_start, VoxelState::Unknown);
  }
  // Ending inside unknown space: not a hole, there is no known free space behind it.
  if (in_gap) return stopAt(gap_start, VoxelState::Unknown);
  return hit;
}

const char* seedStatusName(SeedStatus s) {
  switch (s) {
    case SeedStatus::Accepted: return "accepted";
    case SeedStatus::TooClose: return "too_close";
    case SeedStatus::InsideExisting: return "inside_existing";
    case SeedStatus::Unsafe: return "unsafe";
    case SeedStatus::Deferred: return "deferred";
  }
  return "?";
}

Polyhedron refineHull(const OccupancyMap& map, Polyhedron poly, const Vec3& seed,
                      const SkeletonConfig& cfg) {
  int budget = cfg.refine_rays;
  // Two rounds at most: the second looks at the faces the first one made.
  for (int round = 0; round < 2 && budget > 0; ++round) {
    std::vector<std::pair<double, int>> order;  // (-area, face): largest faces first
    order.reserve(poly.faces.size());
    for (int f = 0; f < int(poly.faces.size()); ++f) {
      // A face whose corners are all free lies inside the sphere of free space already.
      const auto& tri = poly.faces[size_t(f)];
      bool contact = false;
      for (int v : tri) contact = contact || isContact(poly.kinds[size_t(v)]);
      if (contact) order.emplace_back(-poly.faceArea(f), f);
    }
    std::sort(order.begin(), order.end());
    std::vector<Vec3> pts = poly.points;
    std::vector<VertexKind> kinds = poly.kinds;
    bool grew = false;
    for (const auto& [neg_area, f] : order) {
      if (budget <= 0) break;
      const Vec3 c = poly.faceCentroid(f);
      const Vec3 d = c - seed;
      const double dist = d.norm();
      // Only faces the seed sees from inside (the ray through the centroid leaves by this face).
      if (dist < 1e-6 || poly.planeDistance(f, seed) >= -1e-9) continue;
      --budget;
      const Vec3 dir = d / dist;
      const Vec3 end = seed + dir * cfg.max_radius;
      const RayHit hit = castRayThroughGaps(map, seed, end, cfg.unknown_is_contact, cfg.max_unknown_gap);
      const Vec3 p = hit.blocked ? hit.point : end;
      if (poly.planeDistance(f, p) < cfg.refine_min_gain) continue;
      pts.push_back(p);
      kinds.push_back(!hit.blocked ? VertexKind::Free
                      : hit.hit_state == VoxelState::Occupied ? VertexKind::Obstacle
                                                              : VertexKind::Unknown);
      grew = true;
    }
    if (!grew) break;
    Polyhedron refined = buildPolyhedron(std::move(pts), std::move(kinds));
    if (!refined.valid()) break;
    poly = std::move(refined);
  }
  return poly;
}

Polyhedron expandNewPolyhedron(const OccupancyMap& map, const Vec3& seed,
                               const std::vector<Vec3>& directions, const SkeletonConfig& cfg) {
  std::vector<Vec3> pts;
  std::vector<VertexKind> kinds;
  pts.reserve(directions.size());
  kinds.reserve(directions.size());
  for (const Vec3& dir : directions) {
    const Vec3 end = seed + dir * cfg.max_radius;
    const RayHit hit = castRayThroughGaps(map, seed, end, cfg.unknown_is_contact, cfg.max_unknown_gap);
    if (hit.blocked) {
      pts.push_back(hit.point);
      kinds.push_back(hit.hit_state == VoxelState::Occupied ? VertexKind::Obstacle : VertexKind::Unknown);
    } else {
      pts.push_back(end);
      kinds.push_back(VertexKind::Free);
    }
  }
  Polyhedron poly = buildPolyhedron(std::move(pts), std::move(kinds));
  if (cfg.refine_rays > 0 && poly.valid()) poly = refineHull(map, std::move(poly), seed, cfg);
  if (cfg.carve_obstacles) poly = carveObstacles(map, std::move(poly), seed, cfg.max_carve_cuts);
  return poly;
}


std::vector<Vec3> obstacleVoxelsInside(const OccupancyMap& map, const Polyhedron& poly) {
  std::vector<Vec3> out;
  if (!poly.valid()) return out;
  const double res = map.resolution(), h = 0.5 * res;
  const Vec3i lo = map.keyOf(poly.bounds.min), hi = map.keyOf(poly.bounds.max);
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Vec3i k(x, y, z);
        if (map.state(k) != VoxelState::Occupied) continue;
        const Vec3 c = map.centerOf(k);
        if (cubePenetration(poly, c, h) > kTouchFraction * res) out.push_back(c);
      }
  return out;
}

Polyhedron carveObstacles(const OccupancyMap& map, Polyhedron poly, const Vec3& seed, int max_cuts) {
  if (!poly.valid() || max_cuts <= 0) return poly;
  const double res = map.resolution(), h = 0.5 * res, touch = kTouchFraction * res;
  std::vector<std::pair<double, Vec3>> inside;  // (distance to the seed, voxel centre)
  for (const Vec3& c : obstacleVoxelsInside(map, poly)) inside.emplace_back((c - seed).norm(), c);
  // Nearest first: a cut for a near voxel usually removes the ones behind it too.
  std::sort(inside.begin(), inside.end(), [](const auto& a, const auto& b) {
    return std::make_tuple(a.first, a.second.x(), a.second.y(), a.second.z()) <
           std::make_tuple(b.first, b.second.x(), b.second.y(), b.second.z());
  });
  int cuts = 0;
  for (const auto& [dist, c] : inside) {
    if (cubePenetration(poly, c, h) <= touch) continue;
    if (cuts++ >= max_cuts) return Polyhedron{};  // cannot make it obstacle-free
    std::optional<Polyhedron> cut = cutOutCube(poly, c, h, seed);
    if (!cut) return Polyhedron{};  // the seed touches the obstacle
    poly = std::move(*cut);
    if (!poly.valid()) return poly;
  }
  return poly;
}

bool findUnsafeVoxel(const OccupancyMap& map, const Vec3& p, double radius, bool unknown_unsafe,
                     Vec3i* key, VoxelState* state, int unknown_tolerated) {
  const double res = map.resolution();
  const Vec3i c = map.keyOf(p);
  const int n = int(std::ceil(radius / res));
  int unknown = 0;
  Vec3i unknown_key = c;
  for (int dz = -n; dz <= n; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        const Vec3 lo = k.cast<double>() * res, hi = lo + Vec3::Constant(res);
        if ((p.cwiseMax(lo).cwiseMin(hi) - p).norm() > radius) continue;
        const VoxelState st = map.state(k);
        if (st == VoxelState::Occupied) {
          if (key) *key = k;
          if (state) *state = st;
          return true;  // an obstacle decides: no need to look for unknown voxels
        }
        if (unknown_unsafe && st == VoxelState::Unknown && unknown++ == 0) unknown_key = k;
      }
  if (unknown <= unknown_tolerated) return false;
  if (key) *key = unknown_key;
  if (state) *state = VoxelState::Unknown;
  return true;
}

namespace {

// One candidate: a run from `from` along unit `dir`, at most max_extension, stopped by obstacles
// (and unknown space when it is contact); the candidate is the middle of the run.
SeedDecision runCandidate(const Vec3& from, const Vec3& dir, const OccupancyMap& map,
                          const ConnectivityGraph& graph, const SkeletonConfig& cfg) {
  SeedDecision d;
  const bool unknown_blocks = cfg.unknown_is_contact;
  const Vec3i from_key = map.keyOf(from);
  d.position = from;
  d.from = from;
  if (!map.inWindow(from_key)) {
    d.status = SeedStatus::Deferred;
    d.probe = from_key;
    return d;
  }
  const VoxelState from_state = map.state(from_key);
  if (from_state == VoxelState::Occupied) return d;  // Unsafe: the opening sits on an obstacle
  if (from_state == VoxelState::Unknown && unknown_blocks) {
    d.status = SeedStatus::Deferred;
    d.probe = from_key;
    return d;
  }
  const RayHit run = castRayThroughGaps(map, from, from + dir * cfg.max_extension, unknown_blocks,
                                       cfg.max_unknown_gap);
  d.position = from + dir * (0.5 * run.distance);
  // A run cut short by unknown space may grow once that space is observed, moving the candidate
  // out of covered space: such candidates wait instead of being dropped.
  const bool cut_by_unknown = run.blocked && run.hit_state == VoxelState::Unknown;
  const Vec3i cut_key = map.keyOf(run.point + dir * (1e-3 * map.resolution()));
  auto dropOrDefer = [&](SeedStatus drop) {
    d.status = cut_by_unknown ? SeedStatus::Deferred : drop;
    d.probe = cut_key;
    return d;
  };
  // Graph checks first: a candidate in covered space is dropped whatever the map says.
  // Satellites (skeleton.satellite_fill) are invisible to the core graph's growth.
  if (graph.hasCenterWithin(d.position, cfg.min_center_distance, true)) return dropOrDefer(SeedStatus::TooClose);
  if (graph.containingNode(d.position, true) >= 0) return dropOrDefer(SeedStatus::InsideExisting);
  const Vec3i key = map.keyOf(d.position);
  if (!map.inWindow(key)) {
    d.status = SeedStatus::Deferred;
    d.probe = key;
    return d;
  }
  Vec3i bad;
  VoxelState bad_state;
  if (findUnsafeVoxel(map, d.position, cfg.robot_radius, unknown_blocks, &bad, &bad_state,
                      toleratedUnknownVoxels(map, cfg))) {
    if (bad_state == VoxelState::Unknown) {
      d.status = SeedStatus::Deferred;
      d.probe = bad;
    } else {
      d.status = SeedStatus::Unsafe;
    }
    return d;
  }
  d.status = SeedStatus::Accepted;
  return d;
}

}  // namespace

SeedDecision findNewExpandSeed(const BoundarySurface& surface, const OccupancyMap& map,
                               const ConnectivityGraph& graph, const SkeletonConfig& cfg) {
  const SeedDecision primary = runCandidate(surface.nexus, surface.normal, map, graph, cfg);
  if (primary.status == SeedStatus::Accepted || primary.status == SeedStatus::Deferred) return primary;
  if (surface.node < 0 || surface.node >= int(graph.size()) || cfg.seed_retries <= 0) return primary;
  // The nexus of a cluster that spans a wall and a door lies on the wall. Free vertices mark
  // where space does continue: retry along the owner's rays through the ones nearest the nexus.
  const ScgNode& owner = graph.node(surface.node);
  int tries = 0;
  for (const Vec3& v : surface.free_vertices) {
    if (tries++ >= cfg.seed_retries) break;
    const Vec3 dir = (v - owner.seed).normalized();
    const SeedDecision alt = runCandidate(v, dir, map, graph, cfg);
    if (alt.status == SeedStatus::Accepted) return alt;
  }
  return primary;
}

}  // namespace ussnav
