// The reasoner-driven coarse level (see coarse_decider.hpp).

#include "ussnav/reasoning/coarse_decider.hpp"

#include "ussnav/core/timing.hpp"

#include <algorithm>
#include <cmath>

namespace ussnav {

nlohmann::json latencySummary(const std::vector<double>& ms) {
  return {{"median", percentile(ms, 0.5)}, {"p95", percentile(ms, 0.95)}, {"count", ms.size()}};
}

CoarseDecider::CoarseDecider(std::shared_ptr<Reasoner> reasoner, std::shared_ptr<const CommonsensePriors> priors,
                             Instruction instruction, const ReasoningConfig& cfg)
    : reasoner_(std::move(reasoner)), priors_(std::move(priors)), instruction_(std::move(instruction)), cfg_(cfg) {}

void CoarseDecider::setScene(std::vector<RegionSummary> regions, std::map<int, RegionSemantics> semantics) {
  regions_ = std::move(regions);
  semantics_ = std::move(semantics);
}

RegionChooser CoarseDecider::chooser() {
  return [this](const PlanInput& in, const std::vector<RegionCandidate>& c) { return choose(in, c); };
}

int CoarseDecider::choose(const PlanInput& in, const std::vector<RegionCandidate>& candidates) {
  // Where the UAV is, and the visit history.
  int current = -1;
  if (in.region_of && in.graph && in.graph->size() > 0) current = in.region_of(in.graph->nearestNode(in.uav.position));
  if (current >= 0 && (history_.empty() || history_.back() != current)) {
    history_.push_back(current);
    ++visits_[current];
  }
  auto candidate = [&](int region) {
    return std::find_if(candidates.begin(), candidates.end(), [&](const RegionCandidate& c) { return c.region == region; });
  };
  if (cfg_.decision_min_interval_s > 0.0 && candidate(committed_) != candidates.end() &&
      in.time - committed_t_ < cfg_.decision_min_interval_s) {
    ++stats_.kept;
    return committed_;
  }

  CoarseQuery q;
  q.instruction = instruction_;
  q.current_region = current;
  q.last_choice = committed_;
  q.history.assign(history_.size() > 20 ? history_.end() - 20 : history_.begin(), history_.end());
  const double speed = in.uav_cfg ? std::max(in.uav_cfg->max_speed, 0.1) : 1.0;
  for (const RegionSummary& s : regions_) {
    RegionState r;
    r.id = s.id;
    r.adjacent = s.adjacent;
    for (const ObjectBrief& o : s.objects) r.objects.push_back(o.label);
    for (const ObjectBrief& o : s.beyond) r.beyond.push_back(o.label);
    r.corridor_shaped = corridorShaped(s);
    if (auto it = semantics_.find(s.id); it != semantics_.end()) {
      r.label = it->second.label;
      r.description = it->second.description;
    }
    if (auto c = candidate(s.id); c != candidates.end()) {
      r.frontiers = c->targets;
      r.gain = c->gain;
      r.frontier_gain = c->frontier_gain;
      r.cost_s = c->cost_s;
      r.best_utility = c->best_utility;
      r.distance_m = c->cost_s * speed;
    }
    if (auto v = visits_.find(s.id); v != visits_.end()) r.visits = v->second;
    q.regions.push_back(std::move(r));
  }
  if (priors_)
    for (size_t a = 0; a < priors_->rooms().size(); ++a)
      for (size_t b = a; b < priors_->rooms().size(); ++b)
        if (const double w = priors_->adjacency(int(a), int(b)); w >= 0.5)
          q.room_adjacency.push_back({priors_->rooms()[a].name, priors_->rooms()[b].name, w});

  // No candidate lies in a region yet (the first frames): nothing to reason about.
  if (std::none_of(q.regions.begin(), q.regions.end(), [](const RegionState& r) { return r.frontiers > 0; })) {
    ++stats_.no_regions;
    committed_ = -1;
    return -1;
  }
  CoarseDecision d = reasoner_->chooseRegion(q);
  ++stats_.decisions;
  stats_.latency_ms.push_back(d.latency_ms);
  last_query_ = std::move(q);
  last_ = d;
  const int chosen = d.fault.empty() ? d.region : -1;
  if (choices_.empty() || choices_.back().region != chosen || choices_.back().fault != d.fault) {
    if (choices_.size() < kMaxChoices) {
      double chance = 0.0;
      for (const auto& sc : d.scores)
        if (sc.region == chosen) chance = sc.chance;
      choices_.push_back({in.time, in.uav.position, chosen, chance, d.global_utility, d.fault, d.reason});
    } else {
      ++choices_dropped_;
    }
  }
  if (!d.fault.empty()) {
    ++stats_.fallbacks;
    ++stats_.faults[d.fault];
    committed_ = -1;
    return -1;  // the planner's global-utility choice
  }
  stats_.global_utility += d.global_utility;
  if (d.region != committed_) committed_t_ = in.time;
  committed_ = d.region;
  return d.region;
}

nlohmann::json CoarseDecider::report() const {
  return {{"reasoner", reasoner_->name()},
          {"instruction", instruction_.text},
          {"targets", instruction_.targets},
          {"room", instruction_.room},
          {"decisions", stats_.decisions},
          {"kept", stats_.kept},
          {"no_regions", stats_.no_regions},
          {"fallbacks", stats_.fallbacks},
          {"global_utility", stats_.global_utility},
          {"faults", stats_.faults},
          {"decision_ms", latencySummary(stats_.latency_ms)},
          {"choices", [&] {
             nlohmann::json a = nlohmann::json::array();
             for (const Choice& c : choices_)
               a.push_back({{"t", std::round(c.t * 10.0) / 10.0},
                            {"at", {std::round(c.at.x() * 100.0) / 100.0, std::round(c.at.y() * 100.0) / 100.0}},
                            {"region", c.region},
                            {"chance", std::round(c.chance * 1000.0) / 1000.0},
                            {"global_utility", c.global_utility},
                            {"fault", c.fault},
                            {"reason", c.reason}});
             return a;
           }()},
          {"choices_dropped", choices_dropped_}};
}

}  // namespace ussnav
