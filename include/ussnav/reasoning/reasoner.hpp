#pragma once
// Coarse-level reasoners behind one interface (paper Sec. V-B):
//   builtin  offline commonsense (priors.hpp): room type of a region from its objects, the
//            chance that it holds the target, and a utility-weighted choice; no network;
//   llm      an OpenAI-compatible chat model (llm_client.hpp) prompted with the files in
//            prompts/; a failed call or a bad reply is reported as a fault (the caller falls
//            back, see coarse_decider.hpp), a failed label falls back to the builtin label.
// Both read only the scene graph (RegionSummary / CoarseQuery), never the simulator's ground
// truth. labelRegion() and chooseRegion() may block (the LLM); RegionLabeler runs labelling off
// the mapping thread. Implementations are thread-safe for concurrent calls.

#include <memory>
#include <string>

#include "ussnav/core/config.hpp"
#include "ussnav/reasoning/coarse_query.hpp"
#include "ussnav/reasoning/priors.hpp"
#include "ussnav/reasoning/region_semantics.hpp"

namespace ussnav {

class Reasoner {
 public:
  virtual ~Reasoner() = default;
  virtual std::string name() const = 0;
  virtual RegionSemantics labelRegion(const RegionSummary& region) = 0;
  virtual CoarseDecision chooseRegion(const CoarseQuery& query) = 0;
};

// cfg.reasoner selects; throws InputError (reasoning.reasoner / prompts_dir) on an unknown
// name or missing prompt files.
std::shared_ptr<Reasoner> makeReasoner(const ReasoningConfig& cfg, std::shared_ptr<const CommonsensePriors> priors);

// The repository's prompts/ folder (or cfg.prompts_dir when set); empty when not found.
std::filesystem::path promptsDir(const ReasoningConfig& cfg);

}  // namespace ussnav
