#include "ussnav/pipeline/mapper.hpp"

#include <algorithm>
#include <numeric>

namespace ussnav {

Mapper::Mapper(const Config& cfg, MapperOptions opt, std::unique_ptr<Detector> detector)
    : cfg_(cfg),
      opt_(opt),
      grid_(cfg.mapping.grid),
      coverage_(cfg.mapping.coverage, cfg.mapping.grid.resolution),
      graph_(cfg.skeleton),
      regions_(cfg.regions),
      detector_(std::move(detector)) {
  if (opt_.objects && detector_) {
    encoder_ = std::shared_ptr<const TextEncoder>(makeTextEncoder(cfg.perception));
    objects_ = std::make_unique<ObjectLayer>(cfg.objects, encoder_);
  }
}

Mapper::~Mapper() = default;

int Mapper::anchorNode(const Vec3& p) const {
  const int inside = graph_.containingNode(p);
  return inside >= 0 ? inside : graph_.nearestNode(p);
}

int Mapper::anchorObject(const MappedObject& o) const {
  if (o.box.empty()) return -1;
  const Aabb w = grid_.window();
  if (!w.contains(o.box.min) || !w.contains(o.box.max)) return -1;  // the grid cannot tell any more
  const double res = grid_.resolution();
  Aabb near = o.box;  // the object's own voxels may stick out of its box by a voxel
  near.min.array() -= res;
  near.max.array() += res;
  const Vec3 c = o.box.center();
  std::vector<std::pair<double, int>> order;
  for (int id : graph_.nodesWithin(c, kObjectAnchorRadius + 0.5 * o.box.size().norm())) {
    const Vec3& n = graph_.node(id).center;
    const double d = (n.cwiseMax(o.box.min).cwiseMin(o.box.max) - n).norm();
    if (d <= kObjectAnchorRadius && w.contains(n)) order.push_back({d, id});
  }
  std::sort(order.begin(), order.end());
  for (const auto& [d, id] : order) {
    const RayHit h = grid_.castRay(graph_.node(id).center, c, false);
    if (!h.blocked || near.contains(h.point)) return id;
  }
  return -1;
}

MapperFrameReport Mapper::process(const MapperFrame& f) {
  MapperFrameReport rep;
  const Stopwatch total;
  grid_.clearChanges();
  {
    const Stopwatch sw;
    grid_.moveTo(f.pose.position);
    if (f.scan)
      rep.insert = grid_.insertScan(*f.scan);
    if (f.depth && (!f.scan || opt_.fuse_depth)) {
      const InsertStats d = grid_.insertDepth(*f.depth);
      if (!f.scan) rep.insert = d;
    }
    times_.add("grid", sw.ms());
  }
  {
    const Stopwatch sw;
    coverage_.update(grid_);
    times_.add("coverage", sw.ms());
  }
  if (opt_.skeleton) {
    const Stopwatch sw;
    new_occupied_.clear();
    for (const VoxelChange& c : grid_.changes())
      if (c.after == VoxelState::Occupied) new_occupied_.push_back(c.key);
    rep.graph = graph_.update(grid_, f.pose.position, f.time, new_occupied_);
    times_.add("skeleton", sw.ms());
  }
  // Nodes and edges are only ever appended, so a size change is exactly "the graph changed",
  // and the new node ids are the tail [partitioned_nodes_, size).
  if (opt_.skeleton && opt_.regions &&
      (graph_.size() != partitioned_nodes_ || graph_.edges().size() != partitioned_edges_)) {
    const Stopwatch sw;
    WeightedGraphView view = makeGraphView(
        graph_.nodes(), [](const ScgNode& n) { return std::pair<int, Vec3>(n.id, n.center); }, graph_.edges(),
        [](const ScgEdge& e) { return std::tuple<int, int, double>(e.a, e.b, e.weight); });
    for (const ScgNode& n : graph_.nodes())  // satellites take the region of their neighbours
      if (n.satellite) view.satellites.push_back(n.id);
    std::vector<int> added(graph_.size() - partitioned_nodes_);
    std::iota(added.begin(), added.end(), int(partitioned_nodes_));
    rep.regions = regions_.update(view, added);
    rep.regions_updated = true;
    partitioned_nodes_ = graph_.size();
    partitioned_edges_ = graph_.edges().size();
    if (objects_) objects_->setRegionOf([this](int node) { return regions_.regionOf(node); });
    times_.add("regions", sw.ms());
  }
  if (objects_ && f.depth) {
    Stopwatch sw;
    const std::vector<Detection> dets = detector_->detect(*f.depth);
    times_.add("perception", sw.ms());
    const Stopwatch sw2;
    const int node = anchorNode(f.pose.position);
    const int region = node >= 0 ? regions_.regionOf(node) : -1;
    rep.objects = objects_->integrate(dets, *f.depth, node, region, f.time);
    if (opt_.skeleton)  // the objects seen in this frame (the grid around them is fresh)
      objects_->reanchor([&](const MappedObject& o) { return o.last_seen == f.time ? anchorObject(o) : -1; },
                         [this](int n) { return n >= 0 ? regions_.regionOf(n) : -1; });
    times_.add("objects", sw2.ms());
  }
  rep.total_ms = total.ms();
  times_.add("update", rep.total_ms);
  ++frames_;
  return rep;
}

}  // namespace ussnav
