#pragma once
// The goal of an ObjectNav episode: a category named in free text ("bed", "sofa"). An object
// label matches when the text encoder puts it within `threshold` cosine of the goal (synonyms
// such as couch / sofa coincide under the WordNet encoder). The same rule serves the pipeline
// (which mapped object is the target?) and the evaluation (which ground-truth instances are?).
// Matching is cached per label; thread-safe for concurrent const use once built.

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "ussnav/perception/text_encoder.hpp"
#include "ussnav/reasoning/instruction.hpp"

namespace ussnav {

struct World;
struct Object;

class GoalMatcher {
 public:
  // Throws InputError (file "goal") on an empty goal.
  GoalMatcher(std::string goal, std::shared_ptr<const TextEncoder> encoder, double threshold);
  // An instruction's categories (reasoning/instruction.hpp): a label matches when it is within
  // `threshold` of any of them, or when `serves` (optional) accepts it (a functional request's
  // judge, servesRequest: a stove serves "somewhere to cook" whose targets were a pan); such a
  // label's similarity is `threshold`. `goal` is the instruction text, for reports.
  GoalMatcher(std::string goal, std::vector<std::string> targets, std::shared_ptr<const TextEncoder> encoder,
              double threshold, std::function<bool(const std::string&)> serves = {});
  bool matches(const std::string& label) const;
  double similarity(const std::string& label) const;
  const std::string& goal() const { return goal_; }

 private:
  std::string goal_;
  std::vector<std::string> targets_;
  std::function<bool(const std::string&)> serves_;
  std::shared_ptr<const TextEncoder> encoder_;
  double threshold_;
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::string, double> cache_;
};

// The goal of an interpreted instruction: its targets, and for a functional request its judge
// (servesRequest) for labels the targets do not name. Episodes and `eval` build it alike.
GoalMatcher instructionGoal(const Instruction& instruction, std::shared_ptr<const TextEncoder> encoder,
                            double threshold);

// Ground-truth instances of the goal in `world` (evaluation only); with `in_room` (a predicate
// on the ground-truth room type) only those inside a room it accepts.
std::vector<const Object*> goalInstances(const World& world, const GoalMatcher& goal,
                                         const std::function<bool(const std::string&)>& in_room = {});

}  // namespace ussnav
