#pragma once
// Path search on the Spatial Connectivity Graph: start and goal attach to nearby nodes (whose
// polyhedron holds them, else that they see through known free space, else whose polyhedron
// they are just outside of), A* runs over node centres (edge cost = edge polyline length, heuristic = straight
// distance), and the polyline is shortcut by line of sight in the map. Every returned segment is
// collision-free where the grid covers it: graph edges are re-checked against the current map
// (obstacles block) and shortcuts need known free space. Cost: A* over the graph plus one ray
// per edge expanded and O(points^2) rays for shortcutting.

#include <vector>

#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

struct PathSearchOptions {
  int attach_candidates = 8;  // nearest node centres tried for the start and for the goal
  double attach_radius = 0.0; // search radius for them; 0 = skeleton visibility_radius * 2
  bool shortcut = true;
  // An end point outside every polyhedron and out of sight through known free space attaches to
  // a node when the straight segment leaves the node's polyhedron for at most this long, m.
  double unknown_attach_max = 0.5;
  // Edges whose polyline passes within avoid_radius of one of these points are not used (the
  // flight loop's obstacles that blocked a path, once the map has forgotten them).
  std::vector<Vec3> avoid;
  double avoid_radius = 0.3;
};

struct GraphPath {
  bool found = false;
  std::vector<Vec3> points;  // start ... goal
  std::vector<int> nodes;    // graph nodes passed, in order (empty for a direct path)
  double length = 0.0;
};

GraphPath findGraphPath(const ConnectivityGraph& g, const OccupancyMap& map, const Vec3& start,
                        const Vec3& goal, const PathSearchOptions& opt = {});

}  // namespace ussnav
