#pragma once
// The global Spatial Connectivity Graph (paper Sec. IV-A, Algorithm 1): polyhedra of free space
// as nodes; kinematic / overlap / visible / loop edges. update() grows it incrementally from the
// local map: a seed at the UAV when nothing covers it, then Boundary Surfaces popped
// (FindNewExpandSeed -> ExpandNewPolyhedron -> UpdateTopology) up to max_expansions_per_frame;
// surfaces blocked by unknown space are parked and retried once their probe voxel is observed.
// When the queue is empty and budget is left, gap filling (skeleton.gap_fill) seeds a polyhedron
// at the nearest point of a gap_spacing lattice around the UAV that is observed free, outside
// every polyhedron, robot_radius clear and in sight of a node (linked to it by a Visible edge):
// space the Boundary Surfaces never pointed at (behind furniture, beside a narrow door).
// Then, with skeleton.satellite_fill, a finer lattice seeds *satellites*: polyhedra for coverage
// and path search that the core graph never sees while it grows (seed checks, centre distances,
// gap filling, the UAV's mount and loop-edge routes ignore them), that queue no Boundary
// Surfaces, and that the region stage leaves out of Leiden. So the core graph is the same with
// or without them (edges to satellites aside).
// Nodes and edges are never removed or moved and outlive the map window. Deterministic.
// Cost: ~0.2-0.5 ms per expansion; a frame with nothing new costs microseconds.
//
// A polyhedron whose centre lands within min_center_distance of an existing centre is dropped,
// as is one that cannot be linked to its parent by a clear segment or polyline.

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/boundary_surface.hpp"
#include "ussnav/skeleton/polyhedron.hpp"

namespace ussnav {

// Edge weights for the region stage (paper Sec. IV-B): geometric adjacency (overlap, visible,
// a kinematic link whose polyhedra intersect) weighs 1; forced links (a kinematic link whose
// polyhedra do not intersect, a loop edge found only by a grid path around an obstacle) weigh
// skeleton.forced_edge_weight.
enum class EdgeType : uint8_t { Kinematic = 0, Overlap = 1, Visible = 2, Loop = 3 };
constexpr int kEdgeTypeCount = 4;
const char* edgeTypeName(EdgeType t);

struct ScgEdge {
  int a = -1, b = -1;            // node ids, a < b is not implied: a is the older end of a link
  EdgeType type = EdgeType::Kinematic;
  double weight = 1.0;
  double length = 0.0;           // along the polyline
  std::vector<Vec3> via;         // waypoints between node a's and node b's centres (often none)
  bool blocked = false;          // an obstacle was observed on it after it was made: path
                                 // search does not use it (it still joins the two for regions)
};

struct ScgNode {
  int id = -1;
  Vec3 center = Vec3::Zero();    // the paper's N: hull centroid, or the seed when the centroid is
                                 // not clear free space in line of sight of the seed
  Vec3 seed = Vec3::Zero();
  Polyhedron polyhedron;
  double reach = 0.0;            // max distance from center to a hull vertex
  int parent = -1;               // node this one was expanded from (-1: root or UAV seed w/o link)
  bool gap_seed = false;         // seeded by gap filling (parent: the node that saw the seed)
  bool satellite = false;        // a satellite (gap_seed too): see the file comment
  double created_time = 0.0;
  int64_t created_frame = 0;
  std::vector<int> edges;        // indices into ConnectivityGraph::edges()
  // Occupied voxel centres inside the hull (the hull cut an obstacle's corner), seen when it
  // was made or later; a straight segment inside the hull must avoid them. obstacles_overflow:
  // more than kMaxNodeObstacles, so the hull cannot be trusted as free space at all.
  std::vector<Vec3> obstacles;
  bool obstacles_overflow = false;
};
constexpr size_t kMaxNodeObstacles = 512;

// What one update() did.
struct GraphUpdateStats {
  int expansions = 0;        // ExpandNewPolyhedron calls
  int nodes_added = 0;
  int edges_added = 0;
  int surfaces_popped = 0;
  int retried = 0;           // deferred surfaces whose probe was observed, re-queued
  int deferred = 0;          // surfaces parked this frame
  int dropped = 0;           // surfaces whose seed was too close / inside / unsafe
  int rejected_polyhedra = 0;// expansions dropped: degenerate hull, centre too close, no link
  bool seeded_at_uav = false;
  int gap_seeds = 0;         // expansions at gap seeds (observed free space nothing covered)
  int satellite_seeds = 0;   // of which satellite seeds
  int recarved = 0;          // polyhedra that took in a newly observed obstacle (recorded or cut)
  int blocked_edges = 0;     // edges found crossing newly observed obstacles
  double ms = 0.0;
};

class ConnectivityGraph {
 public:
  explicit ConnectivityGraph(const SkeletonConfig& cfg = {});

  // One frame: grows the graph where the known free space of `map` allows (see file comment).
  // `new_occupied`: voxels that became Occupied since the last update (RollingGrid::changes());
  // each is recorded in the polyhedra it reaches into (ScgNode::obstacles; cut out of them with
  // skeleton.carve_obstacles), and edges that now cross an obstacle are marked blocked.
  // Centres, ids and edges stay.
  GraphUpdateStats update(const OccupancyMap& map, const Vec3& uav_position, double time,
                          const std::vector<Vec3i>& new_occupied = {});

  const SkeletonConfig& config() const { return cfg_; }
  const std::vector<ScgNode>& nodes() const { return nodes_; }
  const ScgNode& node(int id) const { return nodes_[size_t(id)]; }
  const std::vector<ScgEdge>& edges() const { return edges_; }
  size_t size() const { return nodes_.size(); }
  int64_t frame() const { return frame_; }

  // Index of the edge joining a and b, or -1.
  int edgeBetween(int a, int b) const;
  // Neighbour ids of `id`, ascending.
  std::vector<int> neighbors(int id) const;
  // Full polyline of an edge from node a's centre to node b's centre.
  std::vector<Vec3> edgePolyline(int edge) const;
  // Nodes with created_time > t, ascending id ("what is new since t").
  std::vector<int> nodesCreatedSince(double t) const;
  // Nodes whose centre is within r of p, nearest first (ties: lower id).
  std::vector<int> nodesWithin(const Vec3& p, double r) const;
  // core_only: satellites do not count.
  bool hasCenterWithin(const Vec3& p, double r, bool core_only = false) const;
  // Nearest node centre to p, or -1 when the graph is empty.
  int nearestNode(const Vec3& p) const;
  // Lowest-id node whose polyhedron contains p, or -1 (core_only: the lowest-id core node).
  int containingNode(const Vec3& p, bool core_only = false) const;
  // Boundary surfaces waiting in the expansion queue / parked until unknown space is observed.
  size_t queuedSurfaces() const { return queue_.size(); }
  size_t deferredSurfaces() const { return deferred_.size(); }

 private:
  struct Deferred {
    BoundarySurface surface;
    Vec3i probe;
  };
  // Expands at `seed`, links to `parent` through `hints` (extra waypoints allowed for the
  // kinematic edge), runs UpdateTopology and queues the new Boundary Surfaces. -1 if rejected.
  int addNode(const OccupancyMap& map, const Vec3& seed, int parent, const std::vector<Vec3>& hints,
              bool require_parent_link, double time, GraphUpdateStats& stats, bool gap_seed = false,
              bool satellite = false);
  // Newly observed obstacle voxels: recorded in (or, with carve_obstacles, cut out of) the
  // polyhedra they reach into; edges across them blocked (see update()).
  void noteNewObstacles(const OccupancyMap& map, const std::vector<Vec3i>& new_occupied,
                         GraphUpdateStats& stats);
  // One gap seed (a satellite seed with `satellite`) expanded (true), or no lattice point needs
  // one now (false).
  bool fillOneGap(const OccupancyMap& map, const Vec3& uav_position, double time, GraphUpdateStats& stats,
                  bool satellite);
  void updateTopology(const OccupancyMap& map, int id, GraphUpdateStats& stats);
  int addEdge(int a, int b, EdgeType type, double weight, std::vector<Vec3> via);
  // Shortest graph distance from `from` to every node within `limit` (others: infinity);
  // core_only: through core nodes alone.
  std::unordered_map<int, double> graphDistances(int from, double limit, bool core_only = false) const;
  void indexNode(int id);
  int64_t cellKey(const Vec3i& c) const;
  Vec3i cellOf(const Vec3& p) const;

  SkeletonConfig cfg_;
  std::vector<Vec3> directions_;
  std::vector<ScgNode> nodes_;
  std::vector<ScgEdge> edges_;
  std::deque<BoundarySurface> queue_;
  std::vector<Deferred> deferred_;
  std::unordered_map<int64_t, std::vector<int>> cells_;  // spatial hash of node centres
  double cell_size_ = 2.0;
  double max_reach_ = 0.0;
  double max_edge_length_ = 0.0;
  int64_t frame_ = 0;
  // Gap-fill lattice points settled for good: covered by a polyhedron, expanded, too close to a
  // centre or next to an obstacle. Others are re-checked at each scan.
  std::unordered_map<int64_t, uint8_t> gap_settled_;
  std::unordered_map<int64_t, uint8_t> satellite_settled_;  // the same for the satellite lattice
  int mount_ = -1;                 // last node that contained the UAV
  Vec3 mount_point_ = Vec3::Zero();// UAV position when it was last inside mount_
};

}  // namespace ussnav
