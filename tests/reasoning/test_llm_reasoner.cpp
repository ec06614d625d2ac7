// The `llm` reasoner against a scripted OpenAI-compatible server on loopback: good answers are
// used, every kind of bad answer becomes the documented fallback and is counted.

#include <gtest/gtest.h>

#include "support/test_priors.hpp"

#include "support/fake_llm_server.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/reasoning/coarse_decider.hpp"
#include "ussnav/reasoning/reasoner.hpp"

using namespace ussnav;
using Fake = test::FakeLlmServer;

namespace {

using test::priors;

ReasoningConfig llmConfig(const Fake& server) {
  ReasoningConfig cfg;
  cfg.reasoner = "llm";
  cfg.llm.base_url = server.baseUrl();
  cfg.llm.timeout_s = 0.3;
  cfg.llm.retries = 1;
  cfg.llm.backoff_s = 0.01;
  return cfg;
}

RegionSummary bedroom() {
  RegionSummary r;
  r.id = 5;
  r.nodes = 4;
  r.objects = {{1, "bed", Vec3(1, 2, 0.3), Vec3(2, 1.6, 0.5), 6}, {2, "wardrobe", Vec3(0.2, 3, 1), Vec3(0.6, 1.2, 2), 4}};
  return r;
}

}  // namespace

TEST(LlmReasoner, LabelsARegionAndSendsItsObjects) {
  Fake server;
  server.push(Fake::Behaviour::content(R"({"label": "Bedroom", "description": "A bedroom with a bed."})"));
  auto R = makeReasoner(llmConfig(server), priors());
  EXPECT_EQ(R->name(), "llm");
  const RegionSemantics s = R->labelRegion(bedroom());
  EXPECT_EQ(s.label, "bedroom");
  EXPECT_EQ(s.description, "A bedroom with a bed.");
  EXPECT_EQ(s.source, "llm");
  ASSERT_EQ(server.requestCount(), 1u);
  const auto body = nlohmann::json::parse(server.requests()[0].body);
  const std::string user = body["messages"][1]["content"];
  EXPECT_NE(user.find("\"wardrobe\""), std::string::npos) << user;
  EXPECT_NE(user.find("\"objects\""), std::string::npos);
}

TEST(LlmReasoner, ABadLabelReplyFallsBackToTheBuiltinLabel) {
  Fake server;
  server.push(Fake::Behaviour::content("this is not json"));
  auto R = makeReasoner(llmConfig(server), priors());
  const RegionSemantics s = R->labelRegion(bedroom());
  EXPECT_EQ(s.source, "fallback");
  EXPECT_EQ(s.label, "bedroom");  // what the builtin reasoner says
}

TEST(LlmReasoner, EveryFaultFallsBackAndIsCounted) {
  Fake server;
  auto cfg = llmConfig(server);
  Instruction I;
  I.text = "bed";
  I.targets = {"bed"};
  CoarseDecider D(makeReasoner(cfg, priors()), priors(), I, cfg);
  RegionSummary other;
  other.id = 9;
  D.setScene({bedroom(), other}, {});
  PlanInput in;
  const std::vector<RegionCandidate> cands{{5, 2, 40.0, 3.0, 13.0}, {9, 4, 80.0, 6.0, 13.0}};
  server.push(Fake::Behaviour::content(R"({"region": 5, "reason": "a bed was seen"})"));
  EXPECT_EQ(D.choose(in, cands), 5);
  EXPECT_EQ(D.lastDecision().reason, "a bed was seen");
  server.push(Fake::Behaviour::content("region five, definitely"));  // malformed
  EXPECT_EQ(D.choose(in, cands), -1);
  server.push(Fake::Behaviour::content(R"({"region": 77})"));  // unknown id
  EXPECT_EQ(D.choose(in, cands), -1);
  server.push(Fake::Behaviour::httpStatus(429, "0"));  // rate limited once, then fine
  server.push(Fake::Behaviour::content(R"({"region": 9})"));
  EXPECT_EQ(D.choose(in, cands), 9);
  server.push(Fake::Behaviour::httpStatus(500));  // server error on every attempt
  server.push(Fake::Behaviour::httpStatus(500));
  EXPECT_EQ(D.choose(in, cands), -1);
  server.push(Fake::Behaviour::hang(2.0));  // no answer within the timeout, twice
  server.push(Fake::Behaviour::hang(2.0));
  EXPECT_EQ(D.choose(in, cands), -1);
  const auto& st = D.stats();
  EXPECT_EQ(st.decisions, 6);
  EXPECT_EQ(st.fallbacks, 4);
  EXPECT_EQ(st.faults.at("malformed"), 1);
  EXPECT_EQ(st.faults.at("unknown_region"), 1);
  EXPECT_EQ(st.faults.size(), 4u) << D.report().dump();
  // The query sent is the documented schema.
  const auto body = nlohmann::json::parse(server.requests()[0].body);
  const std::string user = body["messages"][1]["content"];
  const auto q = nlohmann::json::parse(user.substr(user.find('{'), user.rfind('}') - user.find('{') + 1));
  EXPECT_EQ(q["instruction"], "bed");
  EXPECT_EQ(q["regions"].size(), 2u);
  EXPECT_EQ(q["regions"][0]["frontiers"], 2);
}

TEST(LlmReasoner, MissingPromptsAreAClearError) {
  ReasoningConfig cfg;
  cfg.reasoner = "llm";
  cfg.prompts_dir = "/nonexistent/prompts";
  try {
    makeReasoner(cfg, priors());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("region_label.system.txt"), std::string::npos) << e.what();
  }
}
