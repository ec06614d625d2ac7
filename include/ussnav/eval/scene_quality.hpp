#pragma once
// Quality of the region and object layers against the simulator's ground truth (evaluation
// only: the pipeline never reads ground truth). Regions: each graph node's true room is the room
// containing its centre (x, y); nodes outside every room or without a region are skipped; purity
// and ARI of region ids against room ids. Objects: a mapped object matches a GT instance whose
// box (grown by box_margin) contains its centroid, else the nearest box within nearest_max, in
// both cases only when the labels agree (same category or text cosine > label_cosine).
// precision = matched objects / objects, recall = seen instances with a match / seen instances,
// duplicate_rate = objects matched to an already-matched instance / matched objects (in object
// id order). Cost: O(nodes * rooms) and O(objects * instances) plus one encode per label pair.

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ussnav/core/frame.hpp"
#include "ussnav/perception/text_encoder.hpp"
#include "ussnav/scene_graph/scene_graph.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

struct RegionQuality {
  int count = 0;           // regions
  int nodes_scored = 0;    // nodes inside a room and with a region
  int rooms_touched = 0;   // distinct rooms among the scored nodes
  double purity = 1.0;
  double ari = 1.0;
  double largest_share = 0.0;  // the largest region's share of the nodes in regions (1: one for all)
};
RegionQuality regionQuality(const SceneGraph& g, const World& world);

// Region labels (room types named by the reasoner) against the rooms they cover. A region's
// true room is the room holding most of its nodes' centres (ties: lower room id); regions with
// no node in a room are skipped. `room_index` maps a room name or alias to the reasoner's room
// type (-1: a type it cannot name, e.g. "storage"). scored = labelled regions whose true room
// has a type the reasoner can name; correct = those whose label is that type; accuracy =
// correct / scored (0 when none). `confusions` counts the wrong ones as "label <- true type".
struct RegionLabelQuality {
  int regions = 0;      // in a room
  int labelled = 0;     // of those, with a label
  int scored = 0;
  int correct = 0;
  double accuracy = 0.0;
  std::map<std::string, int> confusions;
};
RegionLabelQuality regionLabelQuality(const SceneGraph& g, const World& world,
                                      const std::function<int(const std::string&)>& room_index);

struct ObjectMatchOptions {
  double box_margin = 0.3;     // m
  double nearest_max = 0.5;    // m
  double label_cosine = 0.75;
};

struct ObjectQuality {
  int count = 0;               // mapped objects scored
  int seen_instances = 0;
  int matched_objects = 0;
  int matched_instances = 0;   // seen instances with at least one match
  int duplicates = 0;
  double precision = 0.0, recall = 0.0, duplicate_rate = 0.0;
  std::vector<int> match;      // per mapped object (same order): GT instance id, 0 = none
};
// `seen` holds GT instance ids; `encoder` may be null (labels must then be equal).
ObjectQuality objectQuality(const std::vector<SgObject>& mapped, const World& world, const std::set<int>& seen,
                            const TextEncoder* encoder, const ObjectMatchOptions& opt = {});

// Instance ids that covered at least `min_pixels` pixels of some frame's instance image.
class SeenInstances {
 public:
  explicit SeenInstances(int min_pixels) : min_pixels_(min_pixels) {}
  void add(const DepthFrame& f);
  const std::set<int>& ids() const { return ids_; }

 private:
  int min_pixels_;
  std::set<int> ids_;
};

}  // namespace ussnav
