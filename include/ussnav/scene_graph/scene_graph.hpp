#pragma once
// The scene graph as one plain document (paper Sec. IV: places, regions, objects, plus the
// coverage mask): a snapshot copied out of the live modules, so it can be saved, loaded, drawn
// and compared without them (serialization lives apart, in scene_graph/io.hpp, as in
// spark_dsg). Building it copies every node's hull vertices: O(nodes * V + edges + objects +
// visited cells). Region labels/descriptions stay empty until the semantic stage fills them.

#include <string>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

class Mapper;

struct SgNode {
  int id = -1;
  Vec3 centroid = Vec3::Zero();
  double radius = 0.0;            // reach: max distance from centroid to a hull vertex
  std::vector<Vec3> hull;         // hull vertices, in polyhedron point order
  double created = 0.0;           // seconds
  bool operator==(const SgNode&) const = default;
};

struct SgEdge {
  int a = -1, b = -1;
  std::string type;               // kinematic | overlap | visible | loop
  double weight = 1.0;
  bool blocked = false;           // an obstacle was seen on it later: not for paths
  bool operator==(const SgEdge&) const = default;
};

struct SgRegion {
  int id = -1;
  std::vector<int> nodes;         // ascending
  std::string label, description; // empty until labelled
  Vec3 centroid = Vec3::Zero();
  std::vector<int> adjacent;      // region ids, ascending
  bool operator==(const SgRegion&) const = default;
};

struct SgObject {
  int id = -1;
  std::string label;
  Vec3 centroid = Vec3::Zero();
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();
  int n_observations = 0;
  int node_id = -1;               // -1: not anchored
  int region_id = -1;             // -1: no region
  bool operator==(const SgObject&) const = default;
};

struct SgCoverage {
  double cell_size = 0.0, cell_height = 0.0;  // m
  int64_t visited_cells = 0;
  double explored_area_m2 = 0.0;
  std::vector<Vec3i> visited;     // cell indices (x, y, z), sorted (z, y, x)
  bool operator==(const SgCoverage&) const = default;
};

struct SceneGraph {
  static constexpr int kSchemaVersion = 1;
  static constexpr const char* kFormat = "ussnav-scene-graph";
  int schema_version = kSchemaVersion;
  std::string source;             // free text: what produced it (world file, run)
  double time = 0.0;              // seconds of the snapshot
  std::vector<SgNode> nodes;      // ascending id
  std::vector<SgEdge> edges;
  std::vector<SgRegion> regions;  // ascending id
  std::vector<SgObject> objects;  // ascending id
  SgCoverage coverage;
  bool operator==(const SceneGraph&) const = default;

  // Index into nodes / regions / objects of an id, -1 if absent. O(log n) (ids ascending).
  int nodeIndex(int id) const;
  int regionIndex(int id) const;
};

struct SceneGraphBuildOptions {
  bool confirmed_objects_only = true;  // unconfirmed objects are tentative: leave them out
};

// Snapshot of the Mapper's graph, regions, objects and coverage mask.
SceneGraph buildSceneGraph(const Mapper& m, double time, const std::string& source = "",
                           const SceneGraphBuildOptions& opt = {});

// Per-layer counts (for `ussnav graph stats` and reports).
struct SceneGraphCounts {
  int nodes = 0, edges = 0, regions = 0, objects = 0, labelled_regions = 0;
  std::vector<std::pair<std::string, int>> edges_by_type;     // in type order, zeros included
  std::vector<std::pair<std::string, int>> objects_by_label;  // most frequent first, then name
};
SceneGraphCounts countLayers(const SceneGraph& g);

}  // namespace ussnav
