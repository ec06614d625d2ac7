#pragma once
// Travel distances over the Spatial Connectivity Graph, for ranking viewpoints (paper Sec. V-B:
// costs by A* on the graph). One Dijkstra from the node the UAV is in (or the nearest visible
// one) gives the distance to every node; a point's cost is then the best of its nearby nodes'
// distance plus the straight hop from that node's centre. Edge lengths are the stored polyline
// lengths (not re-checked against the map: findGraphPath does that for the path actually flown).
// Cost: O((V + E) log V) per source, O(k) per query with k nodes near the point.

#include <limits>
#include <vector>

#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

class GraphDistances {
 public:
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  // Distances from `from`: it attaches to its containing node, else to nodes within
  // `attach_radius` in line of sight through known free space, else to the nearest node.
  GraphDistances(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& from, double attach_radius = 3.0);

  // Graph distance to node `id` (kInf when unreachable).
  double toNode(int id) const { return id >= 0 && size_t(id) < dist_.size() ? dist_[size_t(id)] : kInf; }
  // Distance to point p: min over the nodes whose centre is within `radius` of p (or the nearest
  // node when none) of toNode + |centre - p|. Also the node that achieved it.
  double toPoint(const Vec3& p, int* via_node = nullptr, double radius = 2.5) const;
  bool empty() const { return dist_.empty(); }

 private:
  const ConnectivityGraph* g_;
  Vec3 from_;
  std::vector<double> dist_;
};

// Euclidean-plus-graph distance between two arbitrary points (a fresh Dijkstra from `a`).
double graphDistance(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& a, const Vec3& b);

}  // namespace ussnav
