#include "ussnav/episode/goal.hpp"

#include <algorithm>
#include <cctype>

#include "ussnav/core/error.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

namespace {
std::string normalise(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (char& c : s)
    if (c == '_') c = ' ';
  const auto b = s.find_first_not_of(" \t\n"), e = s.find_last_not_of(" \t\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
}  // namespace

GoalMatcher::GoalMatcher(std::string goal, std::shared_ptr<const TextEncoder> encoder, double threshold)
    : goal_(normalise(std::move(goal))), encoder_(std::move(encoder)), threshold_(threshold) {
  if (goal_.empty()) throw InputError("goal", "goal", "an object category is required, e.g. \"bed\"");
  if (!encoder_) throw InputError("goal", "encoder", "a text encoder is required");
  targets_.push_back(goal_);
}

GoalMatcher::GoalMatcher(std::string goal, std::vector<std::string> targets, std::shared_ptr<const TextEncoder> encoder,
                         double threshold, std::function<bool(const std::string&)> serves)
    : goal_(normalise(std::move(goal))), serves_(std::move(serves)), encoder_(std::move(encoder)), threshold_(threshold) {
  for (auto& t : targets)
    if (!normalise(t).empty()) targets_.push_back(normalise(t));
  if (targets_.empty()) throw InputError("goal", "goal", "'" + goal_ + "' names no object category to look for");
  if (!encoder_) throw InputError("goal", "encoder", "a text encoder is required");
}

double GoalMatcher::similarity(const std::string& label) const {
  const std::string l = normalise(label);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = cache_.find(l);
  if (it != cache_.end()) return it->second;
  double s = 0.0;
  for (const auto& t : targets_) s = std::max(s, l == t ? 1.0 : encoder_->similarity(t, l));
  if (s < threshold_ && serves_ && serves_(l)) s = threshold_;  // serves the request as well as a target
  cache_.emplace(l, s);
  return s;
}

bool GoalMatcher::matches(const std::string& label) const { return similarity(label) >= threshold_; }

GoalMatcher instructionGoal(const Instruction& instruction, std::shared_ptr<const TextEncoder> encoder, double threshold) {
  std::function<bool(const std::string&)> serves;
  if (instruction.how == "functional")
    serves = [in = instruction](const std::string& label) { return servesRequest(in, label); };
  return GoalMatcher(instruction.text, instruction.targets, std::move(encoder), threshold, std::move(serves));
}

std::vector<const Object*> goalInstances(const World& world, const GoalMatcher& goal,
                                         const std::function<bool(const std::string&)>& in_room) {
  std::vector<const Object*> out;
  for (const Object& o : world.objects) {
    if (!goal.matches(o.category)) continue;
    if (in_room) {
      const auto r = std::find_if(world.rooms.begin(), world.rooms.end(), [&](const Room& x) { return x.id == o.room_id; });
      if (r == world.rooms.end() || !in_room(r->type)) continue;
    }
    out.push_back(&o);
  }
  return out;
}

}  // namespace ussnav
