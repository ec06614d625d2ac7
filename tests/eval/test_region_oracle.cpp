// The oracle reasoner (evaluation only, an upper bound): regions placed in ground-truth rooms by
// their centroids, chance 1 in a goal room, 1 for frontiers of a room with a door to one, and the
// builtin decision rule on top.

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_priors.hpp"

#include "ussnav/core/error.hpp"
#include "ussnav/eval/region_oracle.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"

using namespace ussnav;

namespace {

using test::priors;

// Rooms A = [0,4], B = [4,8], C = [8,12] (x) by [0,4] (y); doors A-B and B-C; a bed in C, a
// second bed (room_id unset) in A's twin D = [0,4] x [4,8], which has no door.
World corridorOfRooms() {
  World w;
  auto room = [&](int id, double x0, double y0) {
    Room r;
    r.id = id;
    r.type = "room";
    r.polygon = {Vec2(x0, y0), Vec2(x0 + 4, y0), Vec2(x0 + 4, y0 + 4), Vec2(x0, y0 + 4)};
    w.rooms.push_back(r);
  };
  room(1, 0, 0), room(2, 4, 0), room(3, 8, 0), room(4, 0, 4);
  Door ab, bc;
  ab.id = 1, ab.room_a = 1, ab.room_b = 2, ab.center = Vec2(4, 2);
  bc.id = 2, bc.room_a = 3, bc.room_b = 2, bc.center = Vec2(8, 2);
  w.doors = {ab, bc};
  Object bed;
  bed.id = 1, bed.category = "bed", bed.room_id = 3, bed.box.center = Vec3(10, 2, 0.3);
  Object bed2 = bed;
  bed2.id = 2, bed2.room_id = -1, bed2.box.center = Vec3(2, 6, 0.3);
  w.objects = {bed, bed2};
  return w;
}

RegionSummary summary(int id, double x, double y) {
  RegionSummary r;
  r.id = id;
  r.centroid = Vec3(x, y, 1.2);
  r.box_min = r.box_max = r.centroid;
  r.nodes = 5;
  return r;
}

RegionState state(int id, double gain, double frontier_gain, double cost) {
  RegionState r;
  r.id = id;
  r.frontiers = 2;
  r.gain = gain;
  r.frontier_gain = frontier_gain;
  r.cost_s = cost;
  r.best_utility = gain / cost;
  return r;
}

}  // namespace

TEST(RegionOracle, RoomsOfObjectsUseTheirRoomIdElseTheirPosition) {
  const World w = corridorOfRooms();
  EXPECT_EQ(roomsOf(w, {&w.objects[0]}), (std::set<int>{3}));
  EXPECT_EQ(roomsOf(w, {&w.objects[1]}), (std::set<int>{4}));  // room_id -1: the room under it
}

TEST(RegionOracle, ChanceComesFromTheGroundTruthRoomUnderTheRegion) {
  const World w = corridorOfRooms();
  OracleReasoner oracle(w, {3}, std::make_shared<BuiltinReasoner>(priors()));
  oracle.setScene({summary(1, 2, 2), summary(2, 6, 2), summary(3, 10, 2), summary(4, 2, 6), summary(5, 20, 2)});
  // Known-but-unseen space only (no frontier gain): the region's own room counts.
  EXPECT_DOUBLE_EQ(oracle.chance(state(3, 100, 0, 10)), 1.0);
  EXPECT_DOUBLE_EQ(oracle.chance(state(2, 100, 0, 10)), OracleReasoner::kMiss);
  // Frontiers only: half of the value is the next room's; B has a door to C, A does not, D none.
  EXPECT_NEAR(oracle.chance(state(2, 100, 100, 10)), 0.5 * OracleReasoner::kMiss + 0.5, 1e-12);
  EXPECT_NEAR(oracle.chance(state(1, 100, 100, 10)), OracleReasoner::kMiss, 1e-12);
  EXPECT_NEAR(oracle.chance(state(4, 100, 100, 10)), OracleReasoner::kMiss, 1e-12);
  // Outside every room, or a region the scene does not hold: no knowledge.
  EXPECT_DOUBLE_EQ(oracle.chance(state(5, 100, 0, 10)), 0.5);
  EXPECT_DOUBLE_EQ(oracle.chance(state(9, 100, 0, 10)), 0.5);
}

TEST(RegionOracle, PicksTheGoalRoomOverACheaperRegionWhereTheBuiltinReasonerCannotTell) {
  const World w = corridorOfRooms();
  OracleReasoner oracle(w, {3}, std::make_shared<BuiltinReasoner>(priors()));
  oracle.setScene({summary(1, 2, 2), summary(3, 10, 2), summary(4, 2, 6)});
  CoarseQuery q;
  q.instruction = interpretInstruction("bed", *priors());
  q.current_region = 1;
  // No objects anywhere: A and D look ten times better by gain / cost.
  q.regions = {state(1, 300, 0, 3), state(3, 100, 0, 10), state(4, 300, 0, 3)};
  BuiltinReasoner builtin(priors());
  EXPECT_NE(builtin.chooseRegion(q).region, 3);
  const CoarseDecision d = oracle.chooseRegion(q);
  EXPECT_EQ(d.region, 3);
  EXPECT_TRUE(d.fault.empty());
  // Nothing left to explore in C: the next best by the same rule, never a region without targets.
  q.regions[1].frontiers = 0;
  q.regions[1].cost_s = -1.0;
  EXPECT_NE(oracle.chooseRegion(q).region, 3);
  for (auto& r : q.regions) r.frontiers = 0, r.cost_s = -1.0;
  EXPECT_EQ(oracle.chooseRegion(q).fault, "no_frontiers");
}

TEST(RegionOracle, LabelsComeFromTheBuiltinReasonerAndMakeReasonerRefusesTheOracle) {
  const World w = corridorOfRooms();
  OracleReasoner oracle(w, {3}, std::make_shared<BuiltinReasoner>(priors()));
  RegionSummary r = summary(1, 2, 2);
  r.objects.push_back({1, "toilet", r.centroid, Vec3(0.4, 0.4, 0.4), 5});
  r.objects.push_back({2, "sink", r.centroid, Vec3(0.4, 0.4, 0.4), 5});
  EXPECT_EQ(oracle.labelRegion(r).label, "bathroom");
  EXPECT_EQ(oracle.name(), "oracle");
  ReasoningConfig cfg;
  cfg.reasoner = "oracle";
  EXPECT_THROW(makeReasoner(cfg, priors()), InputError);
}

TEST(RegionOracle, OracleLabelsNameEachRegionsTrueRoomTypeAsSurelyAsItsEvidence) {
  World w = corridorOfRooms();
  w.rooms[0].type = "kitchen", w.rooms[1].type = "corridor", w.rooms[2].type = "bedroom", w.rooms[3].type = "attic";
  const auto builtin = std::make_shared<BuiltinReasoner>(priors());
  OracleReasoner oracle(w, {3}, builtin, ChanceRule{}, OracleReasoner::Knows::RoomTypes);
  EXPECT_EQ(oracle.name(), "oracle-labels");
  oracle.setScene({summary(1, 2, 2), summary(2, 6, 2), summary(3, 10, 2), summary(4, 2, 6), summary(5, 20, 2)});
  CoarseQuery q;
  q.instruction = interpretInstruction("bed", *priors());
  // No evidence (no objects with a prior, no corridor shape): unknown, as for the builtin
  // reasoner, whose chance is then the mean affinity m over room types.
  const double m = builtin->targetChance(q, state(3, 100, 0, 10));
  EXPECT_DOUBLE_EQ(oracle.chance(q, state(3, 100, 0, 10)), m);
  // The bedroom with two objects that say "kitchen" (confidence 1 - e^-1): the bed's affinity to
  // a bedroom is the highest (1), so s = (1 - e^-1) * 1 + e^-1 * m; the builtin reads a kitchen.
  RegionState bedroom = state(3, 100, 0, 10);
  bedroom.objects = {"fridge", "stove"};
  EXPECT_NEAR(oracle.chance(q, bedroom), (1.0 - std::exp(-1.0)) + std::exp(-1.0) * m, 1e-12);
  EXPECT_LT(builtin->targetChance(q, bedroom), m);
  // The kitchen with a nightstand and a wardrobe: the builtin reads a bedroom, the oracle knows.
  RegionState kitchen = state(1, 100, 0, 10);
  kitchen.objects = {"nightstand", "wardrobe"};
  EXPECT_GT(builtin->targetChance(q, kitchen), 2.0 * m);
  EXPECT_LT(oracle.chance(q, kitchen), m);
  // A corridor known by its shape alone: a hallway at confidence 0.3 either way. With a bathtub
  // seen in it the builtin reads a bathroom; the oracle still a hallway, now at the confidence of
  // one object, 1 - e^-0.5. The chance is linear in the confidence: s = m + conf (s_1 - m).
  RegionState corridor = state(2, 100, 100, 10);
  corridor.corridor_shaped = true;
  const double s_shape = oracle.chance(q, corridor);
  EXPECT_DOUBLE_EQ(s_shape, builtin->targetChance(q, corridor));
  EXPECT_NE(s_shape, m);
  corridor.objects = {"bathtub"};
  EXPECT_NEAR(oracle.chance(q, corridor) - m, (1.0 - std::exp(-0.5)) / 0.3 * (s_shape - m), 1e-12);
  EXPECT_NE(oracle.chance(q, corridor), builtin->targetChance(q, corridor));
  // A type the priors cannot name, a region outside every room, one the scene lacks: the builtin.
  for (int id : {4, 5, 9}) {
    RegionState r = state(id, 100, 0, 10);
    r.objects = {"fridge"};
    EXPECT_DOUBLE_EQ(oracle.chance(q, r), builtin->targetChance(q, r));
  }
  // The choice: the bedroom over the kitchen next to the UAV, which the builtin reasoner prefers.
  q.current_region = 1;
  RegionState near = state(1, 300, 0, 3), far = state(3, 100, 0, 5);
  near.objects = {"nightstand", "wardrobe"};
  far.objects = {"fridge", "stove"};
  q.regions = {near, far};
  EXPECT_EQ(builtin->chooseRegion(q).region, 1);
  EXPECT_EQ(oracle.chooseRegion(q).region, 3);
  ReasoningConfig cfg;
  cfg.reasoner = "oracle-labels";
  EXPECT_THROW(makeReasoner(cfg, priors()), InputError);
}
