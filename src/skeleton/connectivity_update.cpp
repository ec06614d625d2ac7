// ConnectivityGraph::update — Algorithm 1 of the paper, made incremental: the expansion queue
// and the parked (deferred) Boundary Surfaces persist between frames.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "ussnav/core/error.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"
#include "ussnav/skeleton/expansion.hpp"
#include "ussnav/skeleton/grid_path.hpp"

namespace ussnav {

namespace {
// Grid searches for loop-closure edges per new node (candidates are tried nearest first).
constexpr int kMaxLoopAttempts = 2;
}  // namespace

GraphUpdateStats ConnectivityGraph::update(const OccupancyMap& map, const Vec3& uav_position,
                                           double time, const std::vector<Vec3i>& new_occupied) {
  if (!uav_position.allFinite() || !std::isfinite(time))
    throw InputError("", "uav_position", "expected a finite position and time for the graph update");
  const Stopwatch watch;
  ++frame_;
  GraphUpdateStats st;

  noteNewObstacles(map, new_occupied, st);

  // Parked surfaces whose probe voxel has been observed may now lead somewhere: queue them.
  std::vector<Deferred> still_parked;
  for (Deferred& d : deferred_) {
    const bool observed = map.inWindow(d.probe) &&
                          (!cfg_.unknown_is_contact || map.state(d.probe) != VoxelState::Unknown);
    if (observed) {
      queue_.push_back(std::move(d.surface));
      ++st.retried;
    } else {
      still_parked.push_back(std::move(d));
    }
  }
  deferred_.swap(still_parked);

  // Lines 1-3 of Algorithm 1: a polyhedron at the UAV when nothing covers it yet. Its parent is
  // the node the UAV was last inside, linked along the UAV's own way (it flew there).
  const int inside = containingNode(uav_position, true);
  if (inside >= 0) {
    mount_ = inside;
    mount_point_ = uav_position;
  } else if (!hasCenterWithin(uav_position, cfg_.min_center_distance, true) &&
             map.inWindow(map.keyOf(uav_position)) &&
             map.stateAt(uav_position) != VoxelState::Occupied) {
    std::vector<Vec3> hints;
    if (mount_ >= 0) hints = {mount_point_, uav_position};
    const int id = addNode(map, uav_position, mount_, hints, false, time, st);
    if (id >= 0) {
      st.seeded_at_uav = true;
      mount_ = id;
      mount_point_ = uav_position;
    }
  }

  // Lines 4-9: pop Boundary Surfaces, find seeds, expand. Rejections are cheap, expansions are
  // not: the budget counts expansions, with a generous cap on pops as a backstop.
  const int max_pops = 20 * cfg_.max_expansions_per_frame;
  int pops = 0;
  while (st.expansions < cfg_.max_expansions_per_frame && pops < max_pops) {
    if (queue_.empty()) {
      // Gap filling: only when the surfaces are done, so it never competes with them.
      if (cfg_.gap_fill && fillOneGap(map, uav_position, time, st, false)) continue;
      if (cfg_.satellite_fill && fillOneGap(map, uav_position, time, st, true)) continue;
      break;
    }
    BoundarySurface s = std::move(queue_.front());
    queue_.pop_front();
    ++pops;
    ++st.surfaces_popped;
    const SeedDecision d = findNewExpandSeed(s, map, *this, cfg_);
    if (d.status == SeedStatus::Accepted) {
      addNode(map, d.position, s.node, {d.from, d.position}, true, time, st);
    } else if (d.status == SeedStatus::Deferred) {
      deferred_.push_back({std::move(s), d.probe});
      ++st.deferred;
    } else {
      ++st.dropped;
    }
  }
  st.ms = watch.ms();
  return st;
}

int ConnectivityGraph::addNode(const OccupancyMap& map, const Vec3& seed, int parent,
                               const std::vector<Vec3>& hints, bool require_parent_link,
                               double time, GraphUpdateStats& stats, bool gap_seed, bool satellite) {
  ++stats.expansions;
  const bool unknown_blocks = cfg_.unknown_is_contact;
  Polyhedron poly = expandNewPolyhedron(map, seed, directions_, cfg_);
  if (!poly.valid()) {
    ++stats.rejected_polyhedra;
    return -1;
  }
  // The centroid is the paper's node position, but a hull can cut a corner of an obstacle, so it
  // must be free, clear of obstacles by the robot radius and visible from the seed.
  Vec3 center = seed;
  const Vec3& c = poly.centroid;
  if (map.stateAt(c) == VoxelState::Free &&
      !findUnsafeVoxel(map, c, cfg_.robot_radius, false, nullptr, nullptr) &&
      tubeOfSight(map, seed, c, cfg_.edge_clearance, unknown_blocks))
    center = c;

  // The centroid may have drifted next to an existing centre: the space is covered already.
  const double spacing = satellite  ? cfg_.satellite_min_center_distance
                         : gap_seed ? cfg_.gap_min_center_distance
                                    : cfg_.min_center_distance;
  if (require_parent_link && hasCenterWithin(center, spacing, !satellite)) {
    ++stats.rejected_polyhedra;
    return -1;
  }

  // The kinematic link crosses the parent's polyhedron and the extension run, both checked free
  // when they were made; the parent's centre may have left the window since, so only obstacles
  // block here.
  std::vector<Vec3> via;
  bool linked = false;
  if (parent >= 0) {
    const Vec3 pc = nodes_[size_t(parent)].center;
    // Straight only through observed space (unseen space may hide a wall); the way through the
    // hints was checked when each part was made.
    if (tubeOfSight(map, pc, center, cfg_.edge_clearance, unknown_blocks)) {
      linked = true;
    } else {
      std::vector<Vec3> pts{pc};
      pts.insert(pts.end(), hints.begin(), hints.end());
      pts.push_back(center);
      if (polylineClear(map, pts, false, cfg_.edge_clearance)) {
        pts = shortcutPolyline(map, pts, false, cfg_.edge_clearance);
        via.assign(pts.begin() + 1, pts.end() - 1);
        linked = true;
      }
    }
  }
  if (require_parent_link && !linked) {
    ++stats.rejected_polyhedra;
    return -1;
  }

  ScgNode n;
  n.id = int(nodes_.size());
  n.center = center;
  n.seed = seed;
  for (int v : poly.hullVertices()) n.reach = std::max(n.reach, (poly.points[size_t(v)] - center).norm());
  n.parent = linked ? parent : -1;
  n.gap_seed = gap_seed || satellite;
  n.satellite = satellite;
  n.created_time = time;
  n.created_frame = frame_;
  if (!cfg_.carve_obstacles) {
    n.obstacles = obstacleVoxelsInside(map, poly);
    if (n.obstacles.size() > kMaxNodeObstacles) {
      n.obstacles.resize(kMaxNodeObstacles);
      n.obstacles_overflow = true;
    }
  }
  n.polyhedron = std::move(poly);
  nodes_.push_back(std::move(n));
  const int id = int(nodes_.size()) - 1;
  indexNode(id);
  ++stats.nodes_added;

  if (linked) {
    // A kinematic link without geometric adjacency is a forced link (paper Sec. IV-B).
    const bool adjacent = polyhedraIntersect(nodes_[size_t(parent)].polyhedron, nodes_[size_t(id)].polyhedron);
    // A gap seed's link is a line of sight, not a way the UAV flew.
    addEdge(parent, id, gap_seed ? EdgeType::Visible : EdgeType::Kinematic,
            adjacent ? 1.0 : cfg_.forced_edge_weight, std::move(via));
    ++stats.edges_added;
  }
  updateTopology(map, id, stats);
  if (satellite) return id;  // satellites do not grow the graph

  for (BoundarySurface& s : findBoundarySurfaces(nodes_[size_t(id)].polyhedron, cfg_.max_cluster_faces,
                                                 cfg_.max_normal_divergence_deg)) {
    s.node = id;
    queue_.push_back(std::move(s));
  }
  return id;
}

void ConnectivityGraph::noteNewObstacles(const OccupancyMap& map, const std::vector<Vec3i>& new_occupied,
                                         GraphUpdateStats& stats) {
  const double h = 0.5 * map.resolution(), touch = kTouchFraction * map.resolution();
  for (const Vec3i& k : new_occupied) {
    const Vec3 c = map.centerOf(k);
    for (int id : nodesWithin(c, max_reach_ + 2.0 * h)) {
      ScgNode& n = nodes_[size_t(id)];
      if (cubePenetration(n.polyhedron, c, h) <= touch) continue;
      if (cfg_.carve_obstacles) {
        // An obstacle at the centre itself (the map changed its mind there): record it.
        std::optional<Polyhedron> cut = cutOutCube(n.polyhedron, c, h, n.center);
        if (cut && cut->valid() && cut->contains(n.center)) {
          n.polyhedron = std::move(*cut);
          ++stats.recarved;
          continue;
        }
      }
      if (std::find(n.obstacles.begin(), n.obstacles.end(), c) != n.obstacles.end()) continue;
      if (n.obstacles.size() < kMaxNodeObstacles)
        n.obstacles.push_back(c);
      else
        n.obstacles_overflow = true;
      ++stats.recarved;
    }
  }
  // Edges whose polyline box meets the new obstacles' box: one walk through the map each.
  if (new_occupied.empty() || edges_.empty()) return;
  Aabb box;
  for (const Vec3i& k : new_occupied) box.extend(map.centerOf(k));
  box.min -= Vec3::Constant(h);
  box.max += Vec3::Constant(h);
  const Vec3 mid = 0.5 * (box.min + box.max);
  std::vector<char> seen(edges_.size(), 0);
  for (int id : nodesWithin(mid, 0.5 * (box.max - box.min).norm() + max_edge_length_))
    for (int e : nodes_[size_t(id)].edges) {
      ScgEdge& ed = edges_[size_t(e)];
      if (seen[size_t(e)] || ed.blocked) continue;
      seen[size_t(e)] = 1;
      const std::vector<Vec3> poly = edgePolyline(e);
      Aabb eb;
      for (const Vec3& q : poly) eb.extend(q);
      if ((eb.max.array() < box.min.array()).any() || (eb.min.array() > box.max.array()).any()) continue;
      if (!polylineClear(map, poly, false)) {
        ed.blocked = true;
        ++stats.blocked_edges;
      }
    }
}

bool ConnectivityGraph::fillOneGap(const OccupancyMap& map, const Vec3& uav_position, double time,
                                   GraphUpdateStats& stats, bool satellite) {
  enum : uint8_t { kCovered = 1, kDone = 2 };
  const double s = satellite ? cfg_.satellite_spacing : cfg_.gap_spacing, r = cfg_.gap_scan_radius;
  const double min_center_distance = satellite ? cfg_.satellite_min_center_distance : cfg_.gap_min_center_distance;
  const double clearance = satellite ? cfg_.satellite_clearance : cfg_.gap_clearance;
  const bool core_only = !satellite;  // core gap seeds do not see satellites
  auto& settled = satellite ? satellite_settled_ : gap_settled_;
  const bool unknown_blocks = cfg_.unknown_is_contact;
  const int tolerated = int(std::floor(cfg_.max_unknown_gap / map.resolution() + 1e-9));
  auto latticeKey = [&](const Vec3i& k) { return cellKey(k); };
  const Vec3i lo((uav_position - Vec3::Constant(r)).unaryExpr([&](double v) { return std::floor(v / s); }).cast<int>());
  const Vec3i hi((uav_position + Vec3::Constant(r)).unaryExpr([&](double v) { return std::floor(v / s); }).cast<int>());
  // Candidates nearest the UAV first (ties by key), so the order does not depend on the frame.
  std::vector<std::pair<double, Vec3i>> cands;
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Vec3i k(x, y, z);
        const Vec3 p = (k.cast<double>() + Vec3::Constant(0.5)) * s;
        const double d = (p - uav_position).norm();
        if (d > r || settled.count(latticeKey(k))) continue;
        const Vec3i vk = map.keyOf(p);
        if (!map.inWindow(vk) || map.state(vk) != VoxelState::Free) continue;
        if (containingNode(p, core_only) >= 0) {
          settled[latticeKey(k)] = kCovered;
          continue;
        }
        cands.emplace_back(d, k);
      }
  std::sort(cands.begin(), cands.end(), [](const auto& a, const auto& b) {
    return std::make_tuple(a.first, a.second.x(), a.second.y(), a.second.z()) <
           std::make_tuple(b.first, b.second.x(), b.second.y(), b.second.z());
  });
  for (const auto& [d, k] : cands) {
    const Vec3 p = (k.cast<double>() + Vec3::Constant(0.5)) * s;
    if (hasCenterWithin(p, min_center_distance, core_only)) {
      settled[latticeKey(k)] = kDone;
      continue;
    }
    VoxelState bad = VoxelState::Free;
    if (findUnsafeVoxel(map, p, std::max(cfg_.robot_radius, clearance), unknown_blocks, nullptr, &bad,
                        tolerated)) {
      if (bad == VoxelState::Occupied) settled[latticeKey(k)] = kDone;
      continue;  // unknown nearby: it may clear later
    }
    int parent = -1;
    for (int id : nodesWithin(p, cfg_.visibility_radius)) {
      if (core_only && nodes_[size_t(id)].satellite) continue;
      if (tubeOfSight(map, nodes_[size_t(id)].center, p, cfg_.edge_clearance, unknown_blocks)) {
        parent = id;
        break;
      }
    }
    if (parent < 0) continue;  // no node in sight yet
    settled[latticeKey(k)] = kDone;
    ++stats.gap_seeds;
    stats.satellite_seeds += satellite;
    addNode(map, p, parent, {p}, true, time, stats, true, satellite);
    return true;
  }
  return false;
}

// Lines 10-14: ConnectCollidingNbrs and ConnectVisibleNbrs (ConnectToParent is done by addNode).
void ConnectivityGraph::updateTopology(const OccupancyMap& map, int id, GraphUpdateStats& stats) {
  const bool unknown_blocks = cfg_.unknown_is_contact;
  const Vec3 center = nodes_[size_t(id)].center;
  const double reach = nodes_[size_t(id)].reach;
  const bool self_satellite = nodes_[size_t(id)].satellite;
  const std::vector<int> candidates = nodesWithin(center, std::max(cfg_.visibility_radius, reach + max_reach_));
  std::unordered_map<int, double> route;  // graph distances from id, computed when first needed
  bool route_ready = false;
  int loop_attempts = 0;
  for (int other : candidates) {
    if (other == id || edgeBetween(id, other) >= 0) continue;
    const ScgNode& o = nodes_[size_t(other)];
    const double dist = (o.center - center).norm();
    const bool overlap = dist <= reach + o.reach &&
                         polyhedraIntersect(nodes_[size_t(id)].polyhedron, o.polyhedron);
    if (!overlap && dist > cfg_.visibility_radius) continue;
    if (tubeOfSight(map, o.center, center, cfg_.edge_clearance, unknown_blocks)) {
      addEdge(other, id, overlap ? EdgeType::Overlap : EdgeType::Visible, 1.0, {});
      ++stats.edges_added;
      continue;
    }
    // Not in sight: a loop-closure edge along a short grid path, unless the graph already joins
    // the two within loop_path_max (then the edge would add nothing but cost). Core nodes only:
    // satellites neither make loop edges nor shorten the routes that decide them.
    if (cfg_.loop_path_max <= 0.0 || self_satellite || o.satellite) continue;
    if (!route_ready) {
      route = graphDistances(id, cfg_.loop_path_max, true);
      route_ready = true;
    }
    if (route.count(other)) continue;
    // Failed searches fill their whole ellipsoid (~1 ms); the nearest few candidates suffice.
    if (loop_attempts++ >= kMaxLoopAttempts) continue;
    // Cells of about the robot radius: far cheaper, and a gap they miss is too narrow to fly.
    const int cell = std::max(1, int(cfg_.robot_radius / map.resolution() + 1e-9));
    const auto path = gridPath(map, o.center, center, cfg_.loop_path_max, unknown_blocks, cell, cfg_.edge_clearance);
    if (!path) continue;
    std::vector<Vec3> via(path->begin() + 1, path->end() - 1);
    if (overlap)
      addEdge(other, id, EdgeType::Overlap, 1.0, std::move(via));
    else
      addEdge(other, id, EdgeType::Loop, cfg_.forced_edge_weight, std::move(via));
    ++stats.edges_added;
    route_ready = false;
  }
}

}  // namespace ussnav
