#include "ussnav/eval/scene_quality.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "ussnav/regions/partition_metrics.hpp"

namespace ussnav {

RegionQuality regionQuality(const SceneGraph& g, const World& world) {
  RegionQuality q;
  q.count = int(g.regions.size());
  std::unordered_map<int, int> region_of;
  size_t largest = 0;
  for (const SgRegion& r : g.regions) {
    for (int n : r.nodes) region_of[n] = r.id;
    largest = std::max(largest, r.nodes.size());
  }
  q.largest_share = region_of.empty() ? 0.0 : double(largest) / double(region_of.size());
  std::vector<int> pred, truth;
  std::set<int> rooms;
  for (const SgNode& n : g.nodes) {
    auto it = region_of.find(n.id);
    const Room* room = world.roomAt(Vec2(n.centroid.x(), n.centroid.y()));
    if (it == region_of.end() || !room) continue;
    pred.push_back(it->second);
    truth.push_back(room->id);
    rooms.insert(room->id);
  }
  q.nodes_scored = int(pred.size());
  q.rooms_touched = int(rooms.size());
  q.purity = purity(pred, truth);
  q.ari = adjustedRandIndex(pred, truth);
  return q;
}

RegionLabelQuality regionLabelQuality(const SceneGraph& g, const World& world,
                                      const std::function<int(const std::string&)>& room_index) {
  RegionLabelQuality q;
  std::unordered_map<int, const SgNode*> node;
  for (const SgNode& n : g.nodes) node[n.id] = &n;
  std::unordered_map<int, const Room*> room_by_id;
  for (const Room& r : world.rooms) room_by_id[r.id] = &r;
  for (const SgRegion& r : g.regions) {
    std::map<int, int> votes;  // room id -> nodes
    for (int id : r.nodes) {
      const auto it = node.find(id);
      if (it == node.end()) continue;
      if (const Room* room = world.roomAt(Vec2(it->second->centroid.x(), it->second->centroid.y()))) ++votes[room->id];
    }
    if (votes.empty()) continue;
    ++q.regions;
    if (r.label.empty()) continue;
    ++q.labelled;
    int best = -1, best_n = 0;
    for (const auto& [room, n] : votes)
      if (n > best_n) best = room, best_n = n;
    const std::string& truth = room_by_id.at(best)->type;
    const int want = room_index(truth);
    if (want < 0) continue;
    ++q.scored;
    if (room_index(r.label) == want) {
      ++q.correct;
    } else {
      ++q.confusions[r.label + " <- " + truth];
    }
  }
  q.accuracy = q.scored > 0 ? double(q.correct) / q.scored : 0.0;
  return q;
}

ObjectQuality objectQuality(const std::vector<SgObject>& mapped, const World& world, const std::set<int>& seen,
                            const TextEncoder* encoder, const ObjectMatchOptions& opt) {
  ObjectQuality q;
  q.count = int(mapped.size());
  q.seen_instances = int(seen.size());
  auto agree = [&](const std::string& a, const std::string& b) {
    return a == b || (encoder && encoder->similarity(a, b) > opt.label_cosine);
  };
  std::set<int> matched_ids;
  for (const SgObject& o : mapped) {
    // Inside a grown box beats nearest-box; among several, the closest box, then the lowest id.
    int best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    bool best_inside = false;
    for (const Object& gt : world.objects) {
      if (!agree(o.label, gt.category)) continue;
      const double d = gt.box.distance(o.centroid);
      const bool inside = gt.box.contains(o.centroid, opt.box_margin);
      if (!inside && d > opt.nearest_max) continue;
      if (best == 0 || (inside && !best_inside) || (inside == best_inside && d < best_d)) {
        best = gt.id;
        best_d = d;
        best_inside = inside;
      }
    }
    q.match.push_back(best);
    if (best == 0) continue;
    ++q.matched_objects;
    if (!matched_ids.insert(best).second) ++q.duplicates;
  }
  for (int id : matched_ids) q.matched_instances += seen.count(id) ? 1 : 0;
  q.precision = q.count ? double(q.matched_objects) / q.count : 0.0;
  q.recall = q.seen_instances ? double(q.matched_instances) / q.seen_instances : 0.0;
  q.duplicate_rate = q.matched_objects ? double(q.duplicates) / q.matched_objects : 0.0;
  return q;
}

void SeenInstances::add(const DepthFrame& f) {
  std::unordered_map<int, int> pixels;
  for (uint16_t id : f.instance)
    if (id) ++pixels[id];
  for (const auto& [id, n] : pixels)
    if (n >= min_pixels_) ids_.insert(id);
}

}  // namespace ussnav
