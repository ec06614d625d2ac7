// The oracle reasoner (see region_oracle.hpp).

#include "ussnav/eval/region_oracle.hpp"

#include <algorithm>

#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/priors.hpp"

namespace ussnav {

OracleReasoner::OracleReasoner(const World& world, std::set<int> goal_rooms, std::shared_ptr<BuiltinReasoner> builtin,
                               ChanceRule rule, Knows knows)
    : world_(world),
      goal_rooms_(std::move(goal_rooms)),
      builtin_(std::move(builtin)),
      rule_(rule),
      knows_(knows) {
  for (const Door& d : world_.doors) {
    if (goal_rooms_.count(d.room_a) && d.room_b >= 0) next_to_goal_.insert(d.room_b);
    if (goal_rooms_.count(d.room_b) && d.room_a >= 0) next_to_goal_.insert(d.room_a);
  }
  // Room types are named once (roomIndex may fall back to the text encoder).
  if (knows_ == Knows::RoomTypes)
    for (const Room& room : world_.rooms) type_of_room_[room.id] = builtin_->priors().roomIndex(room.type);
}

void OracleReasoner::setScene(const std::vector<RegionSummary>& regions) {
  std::map<int, int> rooms;
  for (const RegionSummary& r : regions) {
    const Room* room = world_.roomAt(r.centroid.head<2>());
    rooms[r.id] = room ? room->id : -1;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  room_of_region_ = std::move(rooms);
}

int OracleReasoner::roomOf(int region) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = room_of_region_.find(region);
  return it == room_of_region_.end() ? -1 : it->second;
}

double OracleReasoner::chance(const RegionState& r) const {
  const int room = roomOf(r.id);
  if (room < 0) return 0.5;
  const double self = goal_rooms_.count(room) ? 1.0 : kMiss;
  const double next = next_to_goal_.count(room) ? 1.0 : kMiss;
  return blendChance(r, self, next);
}

double OracleReasoner::chance(const CoarseQuery& q, const RegionState& r) const {
  if (knows_ == Knows::GoalRooms) return chance(r);
  const auto it = type_of_room_.find(roomOf(r.id));
  const int type = it == type_of_room_.end() ? -1 : it->second;
  BuiltinReasoner::RoomBelief belief = builtin_->roomBelief(r);
  if (type >= 0 && belief.confidence > 0.0) {
    std::fill(belief.p.begin(), belief.p.end(), 0.0);
    belief.p[size_t(type)] = 1.0;
  }
  return builtin_->targetChance(q, r, belief);
}

CoarseDecision OracleReasoner::chooseRegion(const CoarseQuery& q) {
  return chooseByChance(q, [&](const RegionState& r) { return chance(q, r); }, rule_);
}

std::set<int> roomsOf(const World& world, const std::vector<const Object*>& objects) {
  std::set<int> out;
  for (const Object* o : objects) {
    if (o->room_id >= 0) {
      out.insert(o->room_id);
    } else if (const Room* room = world.roomAt(o->box.center.head<2>())) {
      out.insert(room->id);
    }
  }
  return out;
}

}  // namespace ussnav
