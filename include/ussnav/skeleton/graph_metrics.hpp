#pragma once
// Measurements of a Spatial Connectivity Graph: counts (nodes, edges by type, parked surfaces)
// as JSON for stats files, and free-space coverage — the fraction of the map's Free voxels in a
// height band that lie inside some polyhedron (the free_space_coverage). Coverage costs
// one point-in-polyhedron test per candidate node per Free voxel of the band.

#include <array>
#include <nlohmann/json.hpp>

#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

struct GraphStats {
  int nodes = 0;
  int edges = 0;
  std::array<int, kEdgeTypeCount> edges_by_type{};  // indexed by EdgeType
  int queued_surfaces = 0;
  int deferred_surfaces = 0;
  double mean_degree = 0.0;
  int components = 0;  // connected components (0 for an empty graph)
  int blocked_edges = 0;       // edges an obstacle observed later lies on
  int nodes_with_obstacles = 0;// hulls known to hold an occupied voxel (a corner they cut)
  int gap_nodes = 0;           // nodes seeded by gap filling (satellites included)
  int satellite_nodes = 0;     // satellites (skeleton.satellite_fill)
};
GraphStats graphStats(const ConnectivityGraph& g);
// {"nodes", "edges", "edges_by_type": {"kinematic", "overlap", "visible", "loop"},
//  "queued_surfaces", "deferred_surfaces", "mean_degree", "components", "blocked_edges",
//  "nodes_with_obstacles", "gap_nodes", "satellite_nodes"}
nlohmann::json toJson(const GraphStats& s);

// Connected component id of every node (ids ascending from 0 in order of the lowest node id).
std::vector<int> connectedComponents(const ConnectivityGraph& g);

struct CoverageResult {
  size_t free_voxels = 0;
  size_t covered_voxels = 0;
  double fraction() const { return free_voxels ? double(covered_voxels) / double(free_voxels) : 0.0; }
};
// Free voxels of `map`'s window whose centre has z in [z_min, z_max], and how many of those
// centres lie inside some node's polyhedron.
CoverageResult freeSpaceCoverage(const ConnectivityGraph& g, const OccupancyMap& map, double z_min,
                                 double z_max);

}  // namespace ussnav
