// The coarse level around a reasoner: faults fall back and are counted, labelling is cached,
// rate-limited and (for slow reasoners) off the caller's thread.

#include <gtest/gtest.h>

#include <atomic>
#include <future>

#include "ussnav/reasoning/coarse_decider.hpp"
#include "ussnav/reasoning/region_labeler.hpp"

using namespace ussnav;

namespace {

// Answers from a script; counts calls; may block until released.
class ScriptedReasoner : public Reasoner {
 public:
  std::vector<CoarseDecision> decisions;
  std::atomic<int> label_calls{0}, decide_calls{0};
  std::shared_future<void> gate;  // labelRegion waits on it when valid
  std::string name() const override { return "scripted"; }
  RegionSemantics labelRegion(const RegionSummary& r) override {
    if (gate.valid()) gate.wait();
    ++label_calls;
    RegionSemantics s;
    s.label = "room " + std::to_string(r.objects.size());
    s.source = name();
    return s;
  }
  CoarseDecision chooseRegion(const CoarseQuery&) override {
    const int i = decide_calls++;
    return decisions.at(size_t(std::min<int>(i, int(decisions.size()) - 1)));
  }
};

RegionSummary summary(int id, std::vector<std::string> labels) {
  RegionSummary r;
  r.id = id;
  r.nodes = 5;
  int k = 0;
  for (auto& l : labels) r.objects.push_back({++k, l, Vec3::Zero(), Vec3::Ones(), 3});
  return r;
}

CoarseDecision decision(int region, std::string fault = "") {
  CoarseDecision d;
  d.region = region;
  d.fault = std::move(fault);
  return d;
}

}  // namespace

TEST(CoarseDecider, FaultsFallBackToUtilityAndAreCounted) {
  auto r = std::make_shared<ScriptedReasoner>();
  r->decisions = {decision(7), decision(-1, "malformed"), decision(42, "unknown_region"), decision(3)};
  r->decisions.back().global_utility = true;  // valid, but the reasoner's semantics did not decide
  ReasoningConfig cfg;
  Instruction I;
  I.text = "bed";
  I.targets = {"bed"};
  CoarseDecider D(r, nullptr, I, cfg);
  D.setScene({summary(3, {}), summary(7, {"wardrobe"})}, {});
  PlanInput in;
  const std::vector<RegionCandidate> cands{{3, 2, 50.0, 4.0, 12.5}, {7, 1, 10.0, 9.0, 1.1}};
  EXPECT_EQ(D.choose(in, cands), 7);
  EXPECT_EQ(D.choose(in, cands), -1);  // -1: the planner's global-utility choice
  EXPECT_EQ(D.choose(in, cands), -1);
  EXPECT_EQ(D.choose(in, cands), 3);
  EXPECT_EQ(D.stats().decisions, 4);
  EXPECT_EQ(D.stats().fallbacks, 2);
  EXPECT_EQ(D.stats().global_utility, 1);
  EXPECT_EQ(D.stats().faults.at("malformed"), 1);
  EXPECT_EQ(D.stats().faults.at("unknown_region"), 1);
  const nlohmann::json rep = D.report();
  EXPECT_EQ(rep["fallbacks"], 2);
  EXPECT_EQ(rep["global_utility"], 1);
  EXPECT_EQ(rep["reasoner"], "scripted");
  // The query carried the candidates' frontiers.
  const RegionState* s7 = D.lastQuery().find(7);
  ASSERT_NE(s7, nullptr);
  EXPECT_EQ(s7->frontiers, 1);
  EXPECT_DOUBLE_EQ(s7->gain, 10.0);
  EXPECT_EQ(s7->objects, std::vector<std::string>{"wardrobe"});
  EXPECT_EQ(D.lastQuery().find(3)->objects.size(), 0u);
}

TEST(CoarseDecider, RateLimitKeepsTheLastRegionWhileItHasFrontiers) {
  auto r = std::make_shared<ScriptedReasoner>();
  r->decisions = {decision(7), decision(3)};
  ReasoningConfig cfg;
  cfg.decision_min_interval_s = 10.0;
  CoarseDecider D(r, nullptr, Instruction{}, cfg);
  D.setScene({summary(3, {}), summary(7, {})}, {});
  PlanInput in;
  std::vector<RegionCandidate> cands{{3, 2, 50.0, 4.0, 12.5}, {7, 1, 10.0, 9.0, 1.1}};
  in.time = 0.0;
  EXPECT_EQ(D.choose(in, cands), 7);
  in.time = 5.0;
  EXPECT_EQ(D.choose(in, cands), 7);  // kept
  EXPECT_EQ(r->decide_calls, 1);
  cands.pop_back();  // region 7 explored: ask again
  EXPECT_EQ(D.choose(in, cands), 3);
  EXPECT_EQ(r->decide_calls, 2);
  EXPECT_EQ(D.stats().kept, 1);
}

TEST(CoarseDecider, LogsTheChoicesAsTheyChange) {
  auto r = std::make_shared<ScriptedReasoner>();
  r->decisions = {decision(7), decision(7), decision(-1, "malformed"), decision(3), decision(3)};
  r->decisions[0].reason = "region 7 (bedroom): chance 0.80";
  r->decisions[0].scores = {{7, 0.8, 1.0}, {3, 0.1, 0.5}};
  CoarseDecider D(r, nullptr, Instruction{}, ReasoningConfig{});
  D.setScene({summary(3, {}), summary(7, {})}, {});
  const std::vector<RegionCandidate> cands{{3, 2, 50.0, 4.0, 12.5}, {7, 1, 10.0, 9.0, 1.1}};
  PlanInput in;
  for (int i = 0; i < 5; ++i) {
    in.time = 2.0 * i;
    in.uav.position = Vec3(i, 0, 1.2);
    D.choose(in, cands);
  }
  ASSERT_EQ(D.choices().size(), 3u);  // 7, the fault, 3: repeats are not logged
  EXPECT_EQ(D.choices()[0].region, 7);
  EXPECT_DOUBLE_EQ(D.choices()[0].chance, 0.8);
  EXPECT_EQ(D.choices()[0].reason, "region 7 (bedroom): chance 0.80");
  EXPECT_EQ(D.choices()[1].region, -1);
  EXPECT_EQ(D.choices()[1].fault, "malformed");
  EXPECT_DOUBLE_EQ(D.choices()[1].t, 4.0);
  EXPECT_EQ(D.choices()[2].region, 3);
  EXPECT_EQ(D.choices()[2].at, Vec3(3, 0, 1.2));
  const nlohmann::json rep = D.report();
  ASSERT_EQ(rep["choices"].size(), 3u);
  EXPECT_EQ(rep["choices"][1]["fault"], "malformed");
  EXPECT_EQ(rep["choices"][2]["at"], nlohmann::json({3.0, 0.0}));
  EXPECT_EQ(rep["choices_dropped"], 0);
}

TEST(RegionLabeler, CachesByContentAndRateLimits) {
  auto r = std::make_shared<ScriptedReasoner>();
  RegionLabeler L(r, 2.0, 16, false);
  L.offer({summary(1, {"bed"}), summary(2, {"sofa"})}, 0.0);
  EXPECT_EQ(r->label_calls, 2);
  L.offer({summary(1, {"bed"}), summary(2, {"sofa"})}, 5.0);  // unchanged: no call
  EXPECT_EQ(r->label_calls, 2);
  L.offer({summary(1, {"bed", "wardrobe"})}, 1.0);  // changed, but too soon
  EXPECT_EQ(r->label_calls, 2);
  L.offer({summary(1, {"bed", "wardrobe"})}, 6.0);
  EXPECT_EQ(r->label_calls, 3);
  EXPECT_EQ(L.semantics().at(1).label, "room 2");
  L.offer({summary(3, {"bed", "wardrobe"})}, 6.0);  // same content as region 1 now: cached
  EXPECT_EQ(r->label_calls, 3);
  EXPECT_EQ(L.semantics().at(3).label, "room 2");
  EXPECT_EQ(L.stats().cache_hits, 1);
  EXPECT_EQ(L.stats().requests, 3);
}

TEST(RegionLabeler, ASlowReasonerDoesNotBlockTheCaller) {
  auto r = std::make_shared<ScriptedReasoner>();
  std::promise<void> release;
  r->gate = release.get_future().share();
  RegionLabeler L(r, 0.0, 2, true);
  // The reasoner blocks until released, yet offer() returns: it only queued the work.
  L.offer({summary(1, {"bed"}), summary(2, {"sofa"}), summary(3, {"toilet"}), summary(4, {"fridge"})}, 0.0);
  EXPECT_TRUE(L.semantics().empty());
  EXPECT_EQ(r->label_calls, 0);
  release.set_value();
  L.drain();
  const auto sem = L.semantics();
  // All four were queued at once into a queue of two: the two oldest were dropped (they will be
  // offered again), the newest two answered.
  EXPECT_EQ(L.stats().dropped, 2);
  EXPECT_EQ(L.stats().labelled, 2);
  EXPECT_EQ(int(sem.size()), L.stats().labelled);
  EXPECT_TRUE(sem.count(4));
}
