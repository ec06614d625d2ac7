#pragma once
// The oracle reasoners (`--reasoner oracle`, `--reasoner oracle-labels`): upper bounds for the
// coarse level, evaluation only — they read the simulator's ground truth and are not navigation
// methods. A region's room is the ground-truth room under its centroid.
//  - `oracle` (Knows::GoalRooms) knows which rooms hold a goal instance. A region's own chance
//    is 1 when its room holds the goal, else kMiss; its frontiers' chance (they look into the
//    room next door) is 1 when a door joins that room to a goal room, else kMiss; a region
//    outside every room gets 0.5 for both. It shows what perfect room-level knowledge would buy.
//  - `oracle-labels` (Knows::RoomTypes) is a perfect region labeller: the builtin chance with
//    the room-type distribution of the builtin belief (BuiltinReasoner::RoomBelief) replaced by
//    the region's true type, at the builtin's confidence (as sure as its evidence: objects with
//    a prior, a corridor's shape; a region with none stays unknown). A region outside every
//    room, or in a room whose type the priors cannot name, keeps the builtin belief. It shows
//    what right region labels would buy the builtin reasoner, all else (the evidence, priors,
//    adjacency, rule) unchanged.
// Both use the builtin decision rule (chooseByChance: chance x best gain / cost, the committed
// region x 1.2). Region labels and descriptions come from the builtin reasoner.

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
  enum class Knows { GoalRooms, RoomTypes };  // `oracle`, `oracle-labels`

  // `goal_rooms`: ids of the world's rooms that hold a goal instance; `builtin` names regions
  // (and gives the chance, with RoomTypes). `world` must outlive the reasoner (the episode's
  // simulator holds it). `rule`: chooseByChance's.
  OracleReasoner(const World& world, std::set<int> goal_rooms, std::shared_ptr<BuiltinReasoner> builtin,
                 ChanceRule rule = {}, Knows knows = Knows::GoalRooms);
  std::string name() const override { return knows_ == Knows::GoalRooms ? "oracle" : "oracle-labels"; }
  RegionSemantics labelRegion(const RegionSummary& region) override { return builtin_->labelRegion(region); }
  CoarseDecision chooseRegion(const CoarseQuery& query) override;

  // The regions of the latest scene-graph snapshot (their centroids place them in rooms).
  void setScene(const std::vector<RegionSummary>& regions);
  // The chance of one region (of the latest scene), as used by chooseRegion (the first form:
  // GoalRooms only, which needs no query).
  double chance(const RegionState& r) const;
  double chance(const CoarseQuery& q, const RegionState& r) const;

 private:
  int roomOf(int region) const;  // the room id, -1 outside every room or unknown region

  const World& world_;
  std::set<int> goal_rooms_, next_to_goal_;
  std::shared_ptr<BuiltinReasoner> builtin_;
  ChanceRule rule_;
  Knows knows_;
  mutable std::mutex mutex_;
  std::map<int, int> room_of_region_;  // region id -> room id, -1 outside every room
  std::map<int, int> type_of_room_;    // RoomTypes: room id -> priors room index, -1 unnamed
};

// Ids of the rooms holding the given objects (their room_id, else the room under their centre).
std::set<int> roomsOf(const World& world, const std::vector<const Object*>& objects);

}  // namespace ussnav
