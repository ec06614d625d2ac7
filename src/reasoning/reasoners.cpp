// The `llm` reasoner and the factory (see reasoner.hpp). The LLM gets the prompt files with
// {{REGION}} / {{QUERY}} replaced by the documented JSON; its replies are validated here.

#include <algorithm>
#include <cctype>
#include <chrono>
#include <fstream>
#include <sstream>

#include "ussnav/core/error.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/llm_client.hpp"
#include "ussnav/reasoning/reasoner.hpp"

namespace ussnav {
namespace {

std::string readPrompt(const std::filesystem::path& dir, const std::string& name) {
  const auto p = dir / name;
  std::ifstream in(p);
  if (!in) throw InputError(p.string(), "reasoning.prompts_dir", "missing prompt file (expected prompts/" + name + ")");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string fill(std::string tmpl, const std::string& key, const std::string& value) {
  const std::string k = "{{" + key + "}}";
  for (size_t pos = tmpl.find(k); pos != std::string::npos; pos = tmpl.find(k, pos + value.size()))
    tmpl.replace(pos, k.size(), value);
  return tmpl;
}

class LlmReasoner : public Reasoner {
 public:
  LlmReasoner(const ReasoningConfig& cfg, std::shared_ptr<const CommonsensePriors> priors)
      : client_(cfg.llm), fallback_(std::move(priors)) {
    const auto dir = promptsDir(cfg);
    if (dir.empty()) throw InputError("prompts", "reasoning.prompts_dir", "prompt folder not found");
    label_system_ = readPrompt(dir, "region_label.system.txt");
    label_user_ = readPrompt(dir, "region_label.user.txt");
    decide_system_ = readPrompt(dir, "coarse_decision.system.txt");
    decide_user_ = readPrompt(dir, "coarse_decision.user.txt");
  }
  std::string name() const override { return "llm"; }

  RegionSemantics labelRegion(const RegionSummary& region) override {
    const LlmReply reply = client_.chat(label_system_, fill(label_user_, "REGION", toJson(region).dump()));
    if (reply.ok()) {
      try {
        const nlohmann::json j = extractJsonObject(reply.content);
        RegionSemantics s;
        s.label = j.at("label").get<std::string>();
        s.description = j.at("description").get<std::string>();
        std::transform(s.label.begin(), s.label.end(), s.label.begin(), [](unsigned char c) { return std::tolower(c); });
        if (s.label == "unknown") s.label.clear();
        s.confidence = s.label.empty() ? 0.0 : 0.8;
        s.source = name();
        s.key = contentKey(region);
        return s;
      } catch (const nlohmann::json::exception&) {
      }
    }
    RegionSemantics s = fallback_.labelRegion(region);
    s.source = "fallback";
    return s;
  }

  CoarseDecision chooseRegion(const CoarseQuery& q) override {
    const LlmReply reply = client_.chat(decide_system_, fill(decide_user_, "QUERY", toJson(q).dump(1)));
    CoarseDecision d;
    if (!reply.ok()) {
      d.fault = std::string("llm_") + toString(reply.status);
      d.reason = reply.error;
    } else {
      d = parseCoarseReply(reply.content, q);
    }
    d.latency_ms = reply.latency_ms;
    return d;
  }

 private:
  LlmClient client_;
  BuiltinReasoner fallback_;
  std::string label_system_, label_user_, decide_system_, decide_user_;
};

}  // namespace

std::filesystem::path promptsDir(const ReasoningConfig& cfg) {
  namespace fs = std::filesystem;
  if (!cfg.prompts_dir.empty()) return cfg.prompts_dir;
  for (fs::path p : {fs::path("prompts"), fs::path(USSNAV_SOURCE_DIR) / "prompts"}) {
    std::error_code ec;
    if (fs::exists(p / "coarse_decision.system.txt", ec)) return p;
  }
  return {};
}

std::shared_ptr<Reasoner> makeReasoner(const ReasoningConfig& cfg, std::shared_ptr<const CommonsensePriors> priors) {
  if (cfg.reasoner == "builtin") return std::make_shared<BuiltinReasoner>(std::move(priors), chanceRule(cfg));
  if (cfg.reasoner == "llm") return std::make_shared<LlmReasoner>(cfg, std::move(priors));
  if (cfg.reasoner == "oracle" || cfg.reasoner == "oracle-labels")
    throw InputError("config", "reasoning.reasoner",
                     "'" + cfg.reasoner + "' reads the simulator's ground truth: only ussnav explore and eval can use it "
                     "(expected builtin or llm here)");
  throw InputError("config", "reasoning.reasoner", "unknown reasoner '" + cfg.reasoner + "' (expected builtin or llm)");
}

}  // namespace ussnav
