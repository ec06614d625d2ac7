// The offline reasoner on hand-made regions: room labels from objects, the region to search for
// a target, the coarse-query schema and the validation of replies.

#include <gtest/gtest.h>

#include "support/test_priors.hpp"

#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/coarse_query.hpp"

using namespace ussnav;

namespace {

using test::priors;

RegionSummary region(int id, std::vector<std::string> labels, Vec3 min = Vec3(0, 0, 1), Vec3 max = Vec3(4, 4, 1)) {
  RegionSummary r;
  r.id = id;
  r.box_min = min;
  r.box_max = max;
  r.centroid = (min + max) / 2;
  r.nodes = 6;
  const Vec3 e = max - min;
  r.elongation = std::max(e.x(), e.y()) / std::max(0.3, std::min(e.x(), e.y()));
  int k = 0;
  for (auto& l : labels) r.objects.push_back({++k, l, r.centroid, Vec3(1, 1, 1), 5});
  return r;
}

RegionState state(int id, std::vector<std::string> objects, int frontiers = 3, double gain = 100, double cost = 10) {
  RegionState r;
  r.id = id;
  r.objects = std::move(objects);
  r.frontiers = frontiers;
  r.gain = gain;
  r.cost_s = frontiers > 0 ? cost : -1.0;
  r.best_utility = frontiers > 0 ? gain / cost : 0.0;  // as if one target held all the gain
  return r;
}

// A kitchen, a bedroom-like room without a bed in view yet, a living room and a bare area.
CoarseQuery house(const std::string& goal) {
  CoarseQuery q;
  q.instruction = interpretInstruction(goal, *priors());
  q.regions = {state(1, {"fridge", "microwave", "sink"}), state(2, {"wardrobe", "nightstand", "alarm clock"}),
               state(3, {"sofa", "coffee table", "television"}), state(4, {})};
  q.current_region = 1;
  return q;
}

}  // namespace

TEST(BuiltinReasoner, LabelsRegionsFromTheirObjects) {
  BuiltinReasoner R(priors());
  EXPECT_EQ(R.labelRegion(region(1, {"bed", "nightstand", "wardrobe"})).label, "bedroom");
  EXPECT_EQ(R.labelRegion(region(2, {"toilet", "sink", "towel"})).label, "bathroom");
  EXPECT_EQ(R.labelRegion(region(3, {"fridge", "stove", "microwave"})).label, "kitchen");
  EXPECT_EQ(R.labelRegion(region(4, {"sofa", "coffee table"})).label, "living room");
  const RegionSemantics corridor = R.labelRegion(region(5, {}, Vec3(0, 0, 1), Vec3(9, 1.2, 1)));
  EXPECT_EQ(corridor.label, "hallway");
  // A corridor's shape counts as one piece of evidence: a plant (a living room's, by the priors)
  // and a trash can do not make a corridor a living room; a toilet and a sink make a narrow
  // washroom a bathroom all the same.
  EXPECT_EQ(R.labelRegion(region(10, {"plant", "trash can"}, Vec3(0, 0, 1), Vec3(9, 1.2, 1))).label, "hallway");
  EXPECT_EQ(R.labelRegion(region(11, {"plant", "trash can"})).label, "living room");
  EXPECT_EQ(R.labelRegion(region(12, {"toilet", "sink"}, Vec3(0, 0, 1), Vec3(6, 1.5, 1))).label, "bathroom");
  // One object alone leaves the label unconfident.
  EXPECT_LT(R.labelRegion(region(9, {"nightstand"})).confidence, 0.3);
  const RegionSemantics bare = R.labelRegion(region(6, {}));
  EXPECT_EQ(bare.label, "");
  EXPECT_DOUBLE_EQ(bare.confidence, 0.0);
  // More evidence, more confidence; the description names the objects.
  const RegionSemantics one = R.labelRegion(region(7, {"bed"}));
  const RegionSemantics three = R.labelRegion(region(8, {"bed", "dresser", "alarm clock"}));
  EXPECT_GT(three.confidence, one.confidence);
  EXPECT_NE(three.description.find("a bed"), std::string::npos) << three.description;
  EXPECT_NE(three.description.find("an alarm clock"), std::string::npos) << three.description;
  // Counts in English: "2 shelves", "2 boxes", not "2 shelfs", "2 boxs"; "an office".
  const RegionSemantics store = R.labelRegion(region(13, {"shelf", "shelf", "box", "box", "person", "person"}));
  EXPECT_NE(store.description.find("2 shelves"), std::string::npos) << store.description;
  EXPECT_NE(store.description.find("2 boxes"), std::string::npos) << store.description;
  EXPECT_NE(store.description.find("2 people"), std::string::npos) << store.description;
  const RegionSemantics office = R.labelRegion(region(14, {"monitor", "monitor", "desk", "office chair"}));
  EXPECT_EQ(office.label, "office");
  EXPECT_EQ(office.description.rfind("An office (", 0), 0u) << office.description;
  EXPECT_EQ(three.source, "builtin");
}

TEST(BuiltinReasoner, EachKindOfObjectCountsOnce) {
  // A room's type is told by the kinds of things in it, not by how many there are of one: six
  // chairs round a table are a dining room, not a living room because chairs are mostly a
  // living room's (apartment-82 "sofa", session 49: a dining room of five chairs was one).
  BuiltinReasoner R(priors());
  const std::vector<std::string> six(6, "chair");
  auto with = [&](std::vector<std::string> v, const std::string& l) { return v.push_back(l), v; };
  EXPECT_EQ(R.labelRegion(region(1, with(six, "table"))).label, "dining room");
  const RegionSemantics one = R.labelRegion(region(2, {"chair"})), many = R.labelRegion(region(3, six));
  EXPECT_EQ(many.label, one.label);
  EXPECT_DOUBLE_EQ(many.confidence, one.confidence);
  ASSERT_EQ(many.room_probs.size(), one.room_probs.size());
  for (size_t k = 0; k < one.room_probs.size(); ++k) EXPECT_DOUBLE_EQ(many.room_probs[k], one.room_probs[k]);
  double known = 0.0;
  R.roomDistribution(with(six, "table"), &known);
  EXPECT_DOUBLE_EQ(known, 2.0);  // two kinds
}

TEST(BuiltinReasoner, RanksTheBedroomLikeRegionFirstForABed) {
  BuiltinReasoner R(priors());
  const CoarseQuery q = house("bed");
  const CoarseDecision d = R.chooseRegion(q);
  EXPECT_TRUE(d.fault.empty()) << d.fault;
  EXPECT_EQ(d.region, 2) << d.reason;
  EXPECT_GT(R.targetChance(q, *q.find(2)), R.targetChance(q, *q.find(1)));
  EXPECT_GT(R.targetChance(q, *q.find(4)), R.targetChance(q, *q.find(1)));  // unknown beats kitchen
  // Other targets, other regions.
  EXPECT_EQ(R.chooseRegion(house("fridge")).region, 1);
  EXPECT_EQ(R.chooseRegion(house("television")).region, 3);
  EXPECT_EQ(R.chooseRegion(house("somewhere to sleep")).region, 2);
}

TEST(BuiltinReasoner, CostAndRoomConstraintsCount) {
  BuiltinReasoner R(priors());
  // The bedroom-like region far away and nearly explored, the bare area close and open: the
  // bare area wins on utility.
  CoarseQuery q = house("bed");
  q.regions[1].cost_s = 200.0;
  q.regions[1].gain = 5.0;
  q.regions[1].best_utility = 5.0 / 200.0;
  q.regions[3].gain = 300.0;
  q.regions[3].cost_s = 5.0;
  q.regions[3].best_utility = 300.0 / 5.0;
  EXPECT_EQ(R.chooseRegion(q).region, 4);
  // A sofa in the living room: not the kitchen region even when it is the only other option.
  CoarseQuery s = house("the sofa in the living room");
  s.regions = {state(1, {"fridge", "stove"}), state(3, {"coffee table", "tv stand"})};
  EXPECT_EQ(R.chooseRegion(s).region, 3);
  // A region already holding the target is chosen (to confirm it).
  CoarseQuery t = house("bed");
  t.regions[2].objects.push_back("bed");
  EXPECT_EQ(R.chooseRegion(t).region, 3);
  // Nothing left to explore anywhere: a fault, not a guess.
  CoarseQuery none = house("bed");
  for (auto& r : none.regions) r.frontiers = 0, r.cost_s = -1;
  EXPECT_EQ(R.chooseRegion(none).fault, "no_frontiers");
}

TEST(BuiltinReasoner, KeepsTheRegionItChoseUnlessAnotherIsClearlyBetter) {
  // Two bare regions, equal chance: the best target of region 5 is worth 100/10, of region 6
  // 110/10. The UAV stands in neither (current region 4, nothing left there). The commitment
  // rule alone (min_chance_ratio 0: see ChanceDecidesOnlyWhenItStandsOut).
  BuiltinReasoner R(priors(), ChanceRule{0.0, 0.0});
  CoarseQuery q;
  q.instruction = interpretInstruction("bed", *priors());
  q.regions = {state(4, {}, 0), state(5, {}, 3, 100, 10), state(6, {}, 3, 110, 10)};
  q.current_region = 4;
  EXPECT_EQ(R.chooseRegion(q).region, 6);  // no earlier choice: the better one
  q.last_choice = 5;
  EXPECT_EQ(R.chooseRegion(q).region, 5);  // chosen before, 10 % worse: kept
  q.regions[2].best_utility = 20;
  EXPECT_EQ(R.chooseRegion(q).region, 6);  // twice as good: switch
  q.regions[2].best_utility = 11;
  q.regions[1] = state(5, {}, 0);          // the chosen region is done: no bonus left for it
  EXPECT_EQ(R.chooseRegion(q).region, 6);
}

TEST(BuiltinReasoner, ChanceDecidesOnlyWhenItStandsOut) {
  // Region 5's best target is worth 100/10, region 6's 60/10. The chance s is given directly.
  CoarseQuery q;
  q.regions = {state(4, {}, 0), state(5, {}, 3, 100, 10), state(6, {}, 3, 60, 10)};
  q.current_region = 4;
  auto choose = [&](double s5, double s6, double ratio, double gap = 0.0) {
    return chooseByChance(q, [&](const RegionState& r) { return r.id == 5 ? s5 : r.id == 6 ? s6 : 0.0; },
                          ChanceRule{ratio, gap});
  };
  // Twice the chance: region 6 is worth (0.40 + 0.02) * 6 = 2.52 against (0.20 + 0.02) * 10 = 2.2.
  EXPECT_EQ(choose(0.20, 0.40, 1.5).region, 6);
  EXPECT_FALSE(choose(0.20, 0.40, 1.5).global_utility);
  // The weighing is reported for every region with targets (region 4 has none).
  const auto scores = choose(0.20, 0.40, 1.5).scores;
  ASSERT_EQ(scores.size(), 2u);
  EXPECT_EQ(scores[0].region, 5);
  EXPECT_DOUBLE_EQ(scores[0].chance, 0.20);
  EXPECT_NEAR(scores[0].value, 2.2, 1e-9);
  EXPECT_EQ(scores[1].region, 6);
  EXPECT_NEAR(scores[1].value, 2.52, 1e-9);
  // 1.5x the chance wins only with the commitment bonus (last choice 6: 0.32 * 6 * 1.2 = 2.30 >
  // 2.2), and 0.30 is under 1.5 x 0.20: too close to act on.
  q.last_choice = 6;
  EXPECT_EQ(choose(0.20, 0.30, 0.0).region, 6);  // rule off: the commitment keeps region 6
  const CoarseDecision d = choose(0.20, 0.30, 1.5);
  EXPECT_EQ(d.region, 5);                          // the global-utility region
  EXPECT_TRUE(d.global_utility);
  EXPECT_NE(d.reason.find("no region's chance stands out"), std::string::npos) << d.reason;
  EXPECT_EQ(choose(0.20, 0.30, 1.25).region, 6);   // 0.30 >= 1.25 x 0.20
  // Near the floor a ratio says little: 0.09 against 0.04 is over 2x, but only 0.05 more.
  EXPECT_EQ(choose(0.04, 0.09, 1.5).region, 6);  // (0.11 x 6 x 1.2 = 0.79 > 0.06 x 10)
  EXPECT_EQ(choose(0.04, 0.09, 1.5, 0.1).region, 5);
  EXPECT_TRUE(choose(0.04, 0.09, 1.5, 0.1).global_utility);
  EXPECT_EQ(choose(0.20, 0.35, 1.5, 0.1).region, 6);  // 1.75x and 0.15 more: acted on
  EXPECT_EQ(choose(0.20, 0.35, 1.5, 0.2).region, 5);  // a wider gap asked for: not
  // Alike regions (no semantics): the best gain / cost target's region even against the bonus.
  q.regions[2] = state(6, {}, 3, 90, 10);
  EXPECT_EQ(choose(0.2, 0.2, 0.0).region, 6);
  EXPECT_EQ(choose(0.2, 0.2, 1.5).region, 5);
}

TEST(BuiltinReasoner, ObjectsSeenBeyondARegionSpeakForItsFrontiers) {
  BuiltinReasoner R(priors());
  CoarseQuery q;
  q.instruction = interpretInstruction("fridge", *priors());
  RegionState none = state(1, {});
  none.frontier_gain = none.gain;  // every target a frontier: half the value is the next room's
  RegionState kitchen = none, bedroom = none, fridge = none;
  kitchen.beyond = {"microwave", "toaster", "coffee machine"};
  bedroom.beyond = {"bed", "alarm clock"};
  fridge.beyond = {"fridge"};
  const double s0 = R.targetChance(q, none);
  EXPECT_GT(R.targetChance(q, kitchen), s0 + 0.1);
  EXPECT_LT(R.targetChance(q, bedroom), s0);
  // The target itself seen beyond: the next room's chance is 1.
  EXPECT_NEAR(R.targetChance(q, fridge), 0.5 * R.targetChance(q, state(1, {})) + 0.5, 1e-12);
  // Without frontiers nothing looks beyond the region: what lies there does not count.
  RegionState inside = kitchen, inside_none = none;
  inside.frontier_gain = inside_none.frontier_gain = 0.0;
  EXPECT_DOUBLE_EQ(R.targetChance(q, inside), R.targetChance(q, inside_none));
}

TEST(CoarseQuery, SerialisesTheDocumentedSchema) {
  CoarseQuery q = house("the sofa in the living room");
  q.history = {1, 3};
  q.regions[0].label = "kitchen";
  q.regions[0].description = "A kitchen.";
  q.regions[0].adjacent = {2, 4};
  q.room_adjacency.push_back({"hallway", "bedroom", 1.0});
  const nlohmann::json j = toJson(q);
  for (const char* k : {"instruction", "targets", "room_constraint", "current_region", "last_choice", "visit_history",
                        "regions", "room_adjacency_prior"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j.size(), 8u);
  EXPECT_EQ(j["instruction"], "the sofa in the living room");
  EXPECT_EQ(j["targets"], nlohmann::json::array({"sofa"}));
  EXPECT_EQ(j["room_constraint"], "living room");
  EXPECT_EQ(j["visit_history"], nlohmann::json::array({1, 3}));
  ASSERT_EQ(j["regions"].size(), 4u);
  const auto& r = j["regions"][0];
  for (const char* k : {"id", "label", "description", "adjacent", "objects", "seen_beyond", "frontiers",
                        "frontier_gain", "unseen_gain", "distance_m", "visits"})
    EXPECT_TRUE(r.contains(k)) << k;
  EXPECT_EQ(r.size(), 11u);
  EXPECT_EQ(r["unseen_gain"], 100.0);  // state() puts all gain in unseen patches
  EXPECT_EQ(r["label"], "kitchen");
  EXPECT_EQ(r["objects"], nlohmann::json::array({"fridge", "microwave", "sink"}));
  EXPECT_EQ(j["room_adjacency_prior"][0], nlohmann::json::array({"hallway", "bedroom", 1.0}));
}

TEST(CoarseQuery, RepliesAreValidated) {
  CoarseQuery q = house("bed");
  q.regions[3].frontiers = 0;
  auto ok = parseCoarseReply(R"({"region": 2, "reason": "wardrobe and nightstand: a bedroom"})", q);
  EXPECT_TRUE(ok.fault.empty());
  EXPECT_EQ(ok.region, 2);
  EXPECT_EQ(ok.reason, "wardrobe and nightstand: a bedroom");
  EXPECT_EQ(parseCoarseReply("Sure! ```json\n{\"region\": \"3\"}\n```", q).region, 3);  // fenced, id as text
  EXPECT_TRUE(parseCoarseReply("Sure! ```json\n{\"region\": \"3\"}\n```", q).fault.empty());
  EXPECT_EQ(parseCoarseReply("I think region two", q).fault, "malformed");
  EXPECT_EQ(parseCoarseReply(R"({"region": "two"})", q).fault, "malformed");
  EXPECT_EQ(parseCoarseReply(R"({"room": 2})", q).fault, "malformed");
  EXPECT_EQ(parseCoarseReply(R"({"region": 2.5})", q).fault, "malformed");
  EXPECT_EQ(parseCoarseReply(R"({"region": 42})", q).fault, "unknown_region");
  EXPECT_EQ(parseCoarseReply(R"({"region": 4})", q).fault, "no_frontiers");
  EXPECT_EQ(parseCoarseReply(R"({"region": 2, "reason": "unclosed)", q).fault, "malformed");
}

TEST(BuiltinReasoner, LooksBeyondFrontiersByRoomAdjacency) {
  // A hallway (a corridor's shape, no objects) and a kitchen, both with frontiers of equal
  // utility and neither holding the target. Bedrooms open onto hallways, not onto kitchens.
  BuiltinReasoner R(priors());
  auto withFrontiers = [](RegionState r) {
    r.frontier_gain = r.gain;
    return r;
  };
  RegionState hall = withFrontiers(state(1, {}));
  hall.corridor_shaped = true;
  const RegionState kitchen = withFrontiers(state(2, {"fridge", "microwave"}));
  CoarseQuery q;
  q.instruction = interpretInstruction("bed", *priors());
  q.regions = {hall, kitchen};
  q.current_region = -1;  // between the two: no stay bonus
  const double s_hall = R.targetChance(q, *q.find(1));
  EXPECT_GT(s_hall, R.targetChance(q, *q.find(2)));
  EXPECT_EQ(R.chooseRegion(q).region, 1) << R.chooseRegion(q).reason;
  // The same hallway whose gain is all known-but-unseen space inside it: nothing beyond it to
  // hope for, so its chance is its own (a hallway seldom holds a bed).
  q.regions[0].frontier_gain = 0.0;
  EXPECT_LT(R.targetChance(q, *q.find(1)), s_hall);
  // For a stove the kitchen keeps its lead: its own chance dominates.
  CoarseQuery k = q;
  k.regions[0].frontier_gain = k.regions[0].gain;
  k.instruction = interpretInstruction("stove", *priors());
  EXPECT_GT(R.targetChance(k, *k.find(2)), R.targetChance(k, *k.find(1)));
  EXPECT_EQ(R.chooseRegion(k).region, 2);
}
