#pragma once
// Incremental region partitioning of the Spatial Connectivity Graph (paper Sec. IV-B): each
// update runs Leiden (CPM) only on the new nodes, the regions they touch and those regions'
// neighbours, consolidates, and matches communities to old regions by node overlap (optimal
// assignment) so ids stay stable and are never reused. Cost: O(N + E) bookkeeping plus Leiden
// on the local subgraph. igraph's RNG is process-global: one update at a time per process.
// Satellite nodes of the view (e.g. the SCG's small gap-filling polyhedra) stay out of Leiden:
// the partition is made on the other nodes alone, then each satellite joins the region of the
// partitioned node nearest to it along the edges (multi-source Dijkstra, centroid distances),
// so a denser graph covers more space without changing where the rooms split. O(E log N).

#include <map>
#include <unordered_map>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/regions/graph_view.hpp"

namespace ussnav {

struct Region {
  int id = -1;
  std::vector<int> nodes;        // node ids, ascending
  Vec3 centroid = Vec3::Zero();  // mean of the node centroids
  std::vector<int> adjacent;     // ids of regions joined to this one by any edge, ascending
};

struct RegionUpdate {
  std::vector<int> created;  // region ids that did not exist before, ascending
  std::vector<int> changed;  // surviving region ids whose node set changed, ascending
  std::vector<int> removed;  // region ids that no longer exist, ascending
  int subgraph_nodes = 0;    // nodes handed to Leiden (0 when nothing needed re-partitioning)
  int subgraph_regions = 0;  // old regions re-partitioned (touched ones and their neighbours)
  int leiden_communities = 0;  // communities Leiden returned, before consolidation
  int merges = 0;            // merges made by consolidation
  double ms = 0.0;           // wall time of the whole update
};

class RegionPartitioner {
 public:
  // Throws InputError when cfg.iterations is 0.
  explicit RegionPartitioner(const RegionsConfig& cfg = {});

  // `g` is the whole current graph; `new_node_ids` the nodes added since the last update.
  // Nodes of `g` that have no region yet count as new even when not listed; a listed node
  // that already has a region keeps it, but its region is re-partitioned. Nodes missing from
  // `g` leave their regions, and regions whose edges changed are re-partitioned as well.
  // Throws InputError on a malformed graph, or a listed or satellite id that is not in `g`.
  // When every node is a satellite, all of them are partitioned.
  RegionUpdate update(const WeightedGraphView& g, const std::vector<int>& new_node_ids);

  // Region id of a node, -1 if the node is unknown.
  int regionOf(int node) const;
  const std::map<int, Region>& regions() const { return regions_; }
  const RegionsConfig& config() const { return cfg_; }

 private:
  RegionsConfig cfg_;
  // Leiden, consolidation and id matching on the partitioned (non-satellite) nodes; fills
  // region_of_ for them. `listed` flags new nodes of `g`.
  void partition(const IndexedGraph& g, const std::vector<char>& listed, RegionUpdate& report);

  std::unordered_map<int, int> region_of_;      // partitioned node id -> region id
  std::unordered_map<int, int> satellite_region_;  // satellite node id -> region id
  std::map<int, Region> regions_;
  std::vector<IndexedEdge> prev_edges_;         // last partitioned graph's edges, by id (u < v)
  int next_id_ = 0;
};

}  // namespace ussnav
