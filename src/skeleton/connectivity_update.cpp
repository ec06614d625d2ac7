// ConnectivityGraph::update — Algorithm 1 of the paper, made incremental: the expansion queue
// and the parked (deferred) Boundary Surfaces persist between frames.
#include <algorithm>
#include <cmath>

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
                                           double time) {
  if (!uav_position.allFinite() || !std::isfinite(time))
    throw InputError("", "uav_position", "expected a finite position and time for the graph update");
  const Stopwatch watch;
  ++frame_;
  GraphUpdateStats st;

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
  const int inside = containingNode(uav_position);
  if (inside >= 0) {
    mount_ = inside;
    mount_point_ = uav_position;
  } else if (!hasCenterWithin(uav_position, cfg_.min_center_distance) &&
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
  while (!queue_.empty() && st.expansions < cfg_.max_expansions_per_frame && pops < max_pops) {
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
                               double time, GraphUpdateStats& stats) {
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
      lineOfSight(map, seed, c, unknown_blocks))
    center = c;

  // The centroid may have drifted next to an existing centre: the space is covered already.
  if (require_parent_link && hasCenterWithin(center, cfg_.min_center_distance)) {
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
    if (lineOfSight(map, pc, center, false)) {
      linked = true;
    } else {
      std::vector<Vec3> pts{pc};
      pts.insert(pts.end(), hints.begin(), hints.end());
      pts.push_back(center);
      if (polylineClear(map, pts, false)) {
        pts = shortcutPolyline(map, pts, false);
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
  n.created_time = time;
  n.created_frame = frame_;
  n.polyhedron = std::move(poly);
  nodes_.push_back(std::move(n));
  const int id = int(nodes_.size()) - 1;
  indexNode(id);
  ++stats.nodes_added;

  if (linked) {
    // A kinematic link without geometric adjacency is a forced link (paper Sec. IV-B).
    const bool adjacent = polyhedraIntersect(nodes_[size_t(parent)].polyhedron, nodes_[size_t(id)].polyhedron);
    addEdge(parent, id, EdgeType::Kinematic, adjacent ? 1.0 : cfg_.forced_edge_weight, std::move(via));
    ++stats.edges_added;
  }
  updateTopology(map, id, stats);

  for (BoundarySurface& s : findBoundarySurfaces(nodes_[size_t(id)].polyhedron, cfg_.max_cluster_faces,
                                                 cfg_.max_normal_divergence_deg)) {
    s.node = id;
    queue_.push_back(std::move(s));
  }
  return id;
}

// Lines 10-14: ConnectCollidingNbrs and ConnectVisibleNbrs (ConnectToParent is done by addNode).
void ConnectivityGraph::updateTopology(const OccupancyMap& map, int id, GraphUpdateStats& stats) {
  const bool unknown_blocks = cfg_.unknown_is_contact;
  const Vec3 center = nodes_[size_t(id)].center;
  const double reach = nodes_[size_t(id)].reach;
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
    if (lineOfSight(map, o.center, center, unknown_blocks)) {
      addEdge(other, id, overlap ? EdgeType::Overlap : EdgeType::Visible, 1.0, {});
      ++stats.edges_added;
      continue;
    }
    // Not in sight: a loop-closure edge along a short grid path, unless the graph already joins
    // the two within loop_path_max (then the edge would add nothing but cost).
    if (cfg_.loop_path_max <= 0.0) continue;
    if (!route_ready) {
      route = graphDistances(id, cfg_.loop_path_max);
      route_ready = true;
    }
    if (route.count(other)) continue;
    // Failed searches fill their whole ellipsoid (~1 ms); the nearest few candidates suffice.
    if (loop_attempts++ >= kMaxLoopAttempts) continue;
    // Cells of about the robot radius: far cheaper, and a gap they miss is too narrow to fly.
    const int cell = std::max(1, int(cfg_.robot_radius / map.resolution() + 1e-9));
    const auto path = gridPath(map, o.center, center, cfg_.loop_path_max, unknown_blocks, cell);
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
