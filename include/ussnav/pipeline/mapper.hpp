#pragma once
// The per-frame scene-graph pipeline (DESIGN.md data flow): rolling grid -> coverage mask ->
// connectivity graph -> regions -> objects. It owns the modules and the order of calls; nothing
// else does. Every stage's wall time goes into times() under its name (grid, coverage, skeleton,
// regions, perception, objects); "regions" is sampled only on frames where the graph changed
// (other frames skip the stage entirely). The grid's change log of the last frame stays readable until the next
// process() call, so evaluation hooks can read what the frame changed.

#include <memory>

#include "ussnav/core/config.hpp"
#include "ussnav/core/frame.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/mapping/coverage_mask.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/objects/object_layer.hpp"
#include "ussnav/perception/detector.hpp"
#include "ussnav/regions/region_partitioner.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

struct MapperOptions {
  bool skeleton = true;  // grow the connectivity graph
  bool objects = true;   // run the detector and the object layer on depth frames
  bool regions = true;   // partition the graph into regions (needs skeleton)
  bool fuse_depth = false;  // with a scan, insert the depth frame into the grid as well (the
                            // camera sees what lies in the LiDAR's blind cone below the UAV)
};

// One frame: the pose and whichever sensors fired. With a scan the scan feeds the grid (the
// paper's LiDAR set-up); without one the depth frame does (camera-only drones).
struct MapperFrame {
  Pose pose;
  const PointCloudScan* scan = nullptr;
  const DepthFrame* depth = nullptr;
  double time = 0.0;
};

struct MapperFrameReport {
  InsertStats insert;
  GraphUpdateStats graph;
  RegionUpdate regions;      // all zero on frames where the graph did not change
  bool regions_updated = false;
  IntegrateStats objects;
  double total_ms = 0.0;
};

class Mapper {
 public:
  // `detector` may be null (no object layer); the text encoder is made from the config.
  Mapper(const Config& cfg, MapperOptions opt, std::unique_ptr<Detector> detector = nullptr);
  ~Mapper();

  MapperFrameReport process(const MapperFrame& frame);

  const RollingGrid& grid() const { return grid_; }
  const CoverageMask& coverage() const { return coverage_; }
  const ConnectivityGraph& graph() const { return graph_; }
  const RegionPartitioner& regions() const { return regions_; }
  const ObjectLayer* objects() const { return objects_.get(); }
  const StageTimes& times() const { return times_; }
  int64_t frames() const { return frames_; }
  // Graph node the UAV is in (or nearest to), -1 before the first node exists.
  int anchorNode(const Vec3& p) const;
  // The node an object belongs to: the node nearest to its box (within kObjectAnchorRadius)
  // whose centre sees the box in the grid, so a stove seen through the kitchen door joins the
  // kitchen's nodes, not the corridor the UAV looked from. -1 when the box is outside the
  // grid window or no node sees it (the object keeps its node). process() re-anchors the
  // objects observed in the frame.
  int anchorObject(const MappedObject& o) const;
  static constexpr double kObjectAnchorRadius = 3.0;

 private:
  Config cfg_;
  MapperOptions opt_;
  RollingGrid grid_;
  CoverageMask coverage_;
  ConnectivityGraph graph_;
  std::vector<Vec3i> new_occupied_;  // scratch: voxels the last insertion made Occupied
  RegionPartitioner regions_;
  size_t partitioned_nodes_ = 0, partitioned_edges_ = 0;  // graph size at the last region update
  std::unique_ptr<Detector> detector_;
  std::shared_ptr<const TextEncoder> encoder_;
  std::unique_ptr<ObjectLayer> objects_;
  StageTimes times_;
  int64_t frames_ = 0;
};

}  // namespace ussnav
