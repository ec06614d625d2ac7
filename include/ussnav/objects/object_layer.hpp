#pragma once
// The object layer of the scene graph (paper Sec. IV-C): detections become world-frame clouds
// and are associated with the existing objects near them. Candidates: objects whose box comes
// within association_radius of the new cloud's centroid (a nanoflann kd-tree over centroids,
// radius grown by the largest object, then the exact box test; for small objects this is the
// paper's centroid query, for a long sofa seen from one end it still finds the sofa). Priority:
// semantic match (cosine > semantic_cos and Omega(new, old) > semantic_overlap), else geometric
// match (Omega > geometric_overlap both ways), else a new object. Then duplicates are merged:
// the object just changed absorbs (or is absorbed by) any object whose label agrees (cosine >
// semantic_cos) and whose box overlaps its box by more than merge_box_overlap of the smaller
// one (both grown by voxel_size); the older id survives and find() maps the absorbed id to it.
// A surface seen from two sides rarely overlaps pointwise, but its boxes do. Each object is anchored to the
// graph node where the UAV was when it was first seen and to that node's region. Not
// thread-safe. Cost per detection: back-projection of its mask, O(|cloud|) per candidate whose
// box touches the new cloud, and a kd-tree rebuild over centroids after a change (n log n).

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/frame.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/perception/detector.hpp"
#include "ussnav/perception/text_encoder.hpp"

namespace ussnav {

struct MappedObject {
  int id = 0;                                          // stable, from 1
  std::string label;                                   // label with the most votes
  std::vector<std::pair<std::string, double>> votes;   // label -> summed score, first-seen order
  Embedding embedding;                                 // unit; score-weighted mean of observations
  std::vector<Vec3f> cloud;                            // world frame, one point per voxel
  Vec3 centroid = Vec3::Zero();                        // mean of cloud
  Aabb box;                                            // of cloud
  int n_observations = 0;
  bool confirmed = false;                              // n_observations >= min_observations_to_confirm
  int node_id = -1;                                    // graph node that sees it (see Mapper::anchorObject)
  int region_id = -1;                                  // that node's region
  double first_seen = 0.0, last_seen = 0.0;            // seconds
  double voxel_size = 0.0;                             // grows when the cloud is coarsened
};

enum class MatchKind { kNone, kSemantic, kGeometric };
const char* toString(MatchKind k);

// Outcome of associating one observation.
struct Association {
  MatchKind kind = MatchKind::kNone;
  bool rejected = false;       // too few points: nothing was changed
  int object_id = 0;           // merged into or created (0 when rejected); after absorption, the survivor
  int absorbed = 0;            // duplicates merged away after this observation
  int candidates = 0;          // objects within association_radius
  double cosine = 0.0;         // of the chosen object (merges only)
  double overlap_new_old = 0;  // Omega(new, old)
  double overlap_old_new = 0;  // Omega(old, new) (computed for geometric checks only)
};

struct IntegrateStats {
  int created = 0, merged_semantic = 0, merged_geometric = 0, rejected = 0;
  int absorbed = 0;  // duplicate objects merged into another
  IntegrateStats& operator+=(const IntegrateStats& o);
};

class ObjectLayer {
 public:
  ObjectLayer(const ObjectsConfig& cfg, std::shared_ptr<const TextEncoder> encoder);
  ~ObjectLayer();
  ObjectLayer(ObjectLayer&&) noexcept;
  ObjectLayer& operator=(ObjectLayer&&) noexcept;

  // One frame's detections, back-projected with the frame's depth, intrinsics and pose.
  // anchor_node / anchor_region: where the UAV is now (used for objects created now).
  IntegrateStats integrate(const std::vector<Detection>& detections, const DepthFrame& frame,
                           int anchor_node, int anchor_region, double time);
  // One observation given as a world-frame cloud (downsampled here). integrate() calls this per
  // detection; tests and dataset replays call it directly.
  Association integrateCloud(const std::vector<Vec3f>& world_points, const std::string& label,
                             double score, int anchor_node, int anchor_region, double time);

  const std::vector<MappedObject>& objects() const { return objects_; }
  // nullptr when no object ever had this id; an absorbed id gives the object that absorbed it.
  const MappedObject* find(int id) const;
  // Objects merged away as duplicates so far.
  int absorbedCount() const { return int(redirect_.size()); }
  // Box overlap used for duplicates: intersection of a and b, each grown by `grow` on every side,
  // over the smaller grown volume (0 when either box is empty).
  static double boxOverlap(const Aabb& a, const Aabb& b, double grow);
  size_t size() const { return objects_.size(); }
  size_t confirmedCount() const;
  // Re-anchors every object's region from its node (the region layer renumbered its regions).
  void setRegionOf(const std::function<int(int node_id)>& region_of);
  // Moves each object to the node `anchor_of` names (-1: keep the current one) and sets its
  // region from that node. Returns how many objects changed node.
  int reanchor(const std::function<int(const MappedObject&)>& anchor_of,
               const std::function<int(int node_id)>& region_of);
  const ObjectsConfig& config() const { return cfg_; }

 private:
  struct State;
  struct CentroidIndex;
  std::vector<int> candidatesNear(const Vec3& centroid);
  void merge(size_t index, const std::vector<Vec3f>& cloud, const std::string& label, double score,
             const Embedding& v, double time);
  void create(const std::vector<Vec3f>& cloud, const std::string& label, double score, const Embedding& v,
              int node, int region, double time);
  // Merges duplicates of objects_[index] (see the header); returns the survivor's index.
  size_t absorbDuplicates(size_t index, int& absorbed);
  void absorb(size_t into, size_t from);  // from's observations join into; from is erased
  void refresh(size_t index);             // box, centroid, label, embedding from the state

  ObjectsConfig cfg_;
  std::shared_ptr<const TextEncoder> encoder_;
  std::vector<MappedObject> objects_;
  std::vector<State> state_;  // parallel to objects_
  std::unordered_map<int, size_t> position_;  // id -> index in objects_
  std::unordered_map<int, int> redirect_;     // absorbed id -> the id that absorbed it
  std::unique_ptr<CentroidIndex> index_;
  int next_id_ = 1;
};

// The object that makes `o` a misreading, if any: another object holding at least `shared` of
// o's points within the layer's tau and seen at least `ratio` times as often. A detector that
// now and then calls a bed "sofa" leaves beside the bed a "sofa" made of those frames alone (a
// partial view overlaps the whole bed one way only, so association keeps it apart); such an
// object is no find. Of several, the most observed; nullptr when there is none.
const MappedObject* outvotedBy(const ObjectLayer& layer, const MappedObject& o, double shared = 0.5,
                               double ratio = 3.0);

// An object observed at `time` (its last_seen) whose label `matches` and whose box lies within
// `radius` of `p`, or nullptr: what the UAV itself sees of a goal from where it stands. A pose
// chosen near an object's box may have a wall between the two that the map had not seen yet;
// from there the detector does not see the object, and nothing may be declared.
const MappedObject* seenWithin(const ObjectLayer& layer, const std::function<bool(const std::string&)>& matches,
                               const Vec3& p, double radius, double time);

}  // namespace ussnav
