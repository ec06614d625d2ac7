#pragma once
// What the reasoners see of a region, and what they say about it (paper Sec. V-B: "the objects
// of a region are serialised and the LLM returns a room label and a description"). A
// RegionSummary is built from a SceneGraph snapshot only (never from ground truth): the region's
// nodes, neighbours and the objects nearest to its nodes. Its JSON (toJson) is the documented
// region-label request (docs/reasoning.md); contentKey() changes when the objects or the shape
// change, so labels can be cached and re-requested only then.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/core/types.hpp"
#include "ussnav/scene_graph/scene_graph.hpp"

namespace ussnav {

struct ObjectBrief {
  int id = -1;
  std::string label;
  Vec3 position = Vec3::Zero();  // centroid, m
  Vec3 size = Vec3::Zero();      // bounding box extent, m
  int n_observations = 0;
};

struct RegionSummary {
  int id = -1;
  Vec3 centroid = Vec3::Zero();
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  // of its node centroids
  int nodes = 0;
  double elongation = 1.0;          // major / minor spread of its node centroids in the plane
  std::vector<int> adjacent;        // region ids
  std::vector<ObjectBrief> objects; // by id
  // Seen from its nodes but lying outside the space they cover (objects in a room not entered
  // yet, seen through its door): evidence about the room next door, not about this one.
  std::vector<ObjectBrief> beyond;
};

// A corridor's shape: node centroids spread at least 3:1 in the plane, over 3 nodes or more.
inline bool corridorShaped(const RegionSummary& s) { return s.nodes >= 3 && s.elongation >= 3.0; }

struct RegionSemantics {
  std::string label;                // room type, e.g. "bedroom"; "" = unknown
  std::string description;          // one sentence
  double confidence = 0.0;          // 0..1
  std::vector<double> room_probs;   // builtin: P(room type) over the priors' rooms; else empty
  std::string source;               // reasoner name, or "fallback"
  uint64_t key = 0;                 // contentKey() of the summary it describes
};

// Regions of a snapshot with their objects: each object goes to the region of its anchor node
// (the node that sees it, so a stove seen through a door joins the kitchen), or, without one,
// of the node whose centroid is nearest to the object's centroid in the plane; to its `beyond`
// list instead when no node of that region reaches it (plane distance from the node's centroid
// above its radius + kReachMargin). Ascending id. The margin, measured on the default and wide
// suites' final graphs against the worlds' rooms: at 0.75 m 23 of 153 objects listed beyond lay
// in the region's own room (a kitchen's counters against its far wall), at 1 m 4 of 129.
constexpr double kReachMargin = 1.0;  // m
std::vector<RegionSummary> summarizeRegions(const SceneGraph& g);
// The region a point belongs to (region of the nearest node in the plane), -1 without nodes.
int regionAt(const SceneGraph& g, const Vec3& p);

nlohmann::json toJson(const RegionSummary& r);
nlohmann::json toJson(const RegionSemantics& s);
// Hash of the object labels (and counts) and the node count bucket (changes by >= 20 %).
uint64_t contentKey(const RegionSummary& r);

}  // namespace ussnav
