#pragma once
// The oracle reasoner (`--reasoner oracle`): an upper bound for the coarse level, evaluation
// only — it reads the simulator's ground truth and is not a navigation method. It knows which
// ground-truth rooms hold a goal instance; a region's room is the room under its centroid. Its
// own chance is 1 when that room holds the goal, else kMiss; its frontiers' chance (they look
// into the room next door) is 1 when a door joins that room to a goal room, else kMiss; a region
// outside every room gets 0.5 for both. The decision rule is the builtin one (chooseByChance:
// chance x best gain / cost, the committed region x 1.2), so `full` with this reasoner shows
// what perfect room-level knowledge would buy the `full` planner. Region labels come from the
// builtin reasoner (room labels play no part in the oracle's choice).

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <vector>

#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/reasoner.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

class OracleReasoner : public Reasoner {
 public:
  static constexpr double kMiss = 0.001;

  // `goal_rooms`: ids of the world's rooms that hold a goal instance; `labels` names regions.
  // `world` must outlive the reasoner (the episode's simulator holds it).
  // `min_chance_ratio`: chooseByChance's (reasoning.min_chance_ratio).
  OracleReasoner(const World& world, std::set<int> goal_rooms, std::shared_ptr<Reasoner> labels,
                 double min_chance_ratio = BuiltinReasoner::kMinChanceRatio);
  std::string name() const override { return "oracle"; }
  RegionSemantics labelRegion(const RegionSummary& region) override { return labels_->labelRegion(region); }
  CoarseDecision chooseRegion(const CoarseQuery& query) override;

  // The regions of the latest scene-graph snapshot (their centroids place them in rooms).
  void setScene(const std::vector<RegionSummary>& regions);
  // The chance of one region (of the latest scene), as used by chooseRegion.
  double chance(const RegionState& r) const;

 private:
  const World& world_;
  std::set<int> goal_rooms_, next_to_goal_;
  std::shared_ptr<Reasoner> labels_;
  double min_chance_ratio_;
  mutable std::mutex mutex_;
  std::map<int, int> room_of_region_;  // region id -> room id, -1 outside every room
};

// Ids of the rooms holding the given objects (their room_id, else the room under their centre).
std::set<int> roomsOf(const World& world, const std::vector<const Object*>& objects);

}  // namespace ussnav
