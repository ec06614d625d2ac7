#pragma once
// The coarse level of the `full` planner (paper Sec. V-B): a RegionChooser that asks a Reasoner
// which region to search. Before each plan the episode hands over the region summaries and
// their semantics (setScene); choose() builds the CoarseQuery (regions with their frontiers,
// gain and cost from the planner's candidates, the visit history, the room-adjacency prior, the
// instruction), asks the reasoner, and returns its region. A fault (malformed reply, unknown
// region, region without frontiers, LLM timeout / HTTP error) is counted and answered with -1,
// which makes the planner fall back to its global-utility choice. With
// decision_min_interval_s > 0 the last decision is kept that long while its region still has
// frontiers (an LLM is then asked at most that often).

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/exploration/planner.hpp"
#include "ussnav/reasoning/reasoner.hpp"

namespace ussnav {

class CoarseDecider {
 public:
  CoarseDecider(std::shared_ptr<Reasoner> reasoner, std::shared_ptr<const CommonsensePriors> priors,
                Instruction instruction, const ReasoningConfig& cfg);

  void setScene(std::vector<RegionSummary> regions, std::map<int, RegionSemantics> semantics);
  int choose(const PlanInput& in, const std::vector<RegionCandidate>& candidates);
  // A RegionChooser calling choose() on this object (which must outlive it).
  RegionChooser chooser();

  struct Stats {
    int decisions = 0;                  // reasoner asked
    int kept = 0;                       // last decision kept (rate limit)
    int no_regions = 0;                 // no candidate in any region yet: utility, no question asked
    int fallbacks = 0;                  // faults answered by global utility
    int global_utility = 0;             // valid replies that were the global-utility choice
                                        // (chance-based reasoners: semantics too weak to act on)
    std::map<std::string, int> faults;  // by kind
    std::vector<double> latency_ms;
  };
  // The coarse level's choices as they changed (one entry each time the region chosen, or a
  // fault, differs from the last): when, where the UAV was, the region and why. For the episode's
  // page (scene_graph.html) and result.json; the first kMaxChoices are kept.
  struct Choice {
    double t = 0.0;
    Vec3 at = Vec3::Zero();
    int region = -1;  // -1: a fault, answered by global utility
    double chance = 0.0;
    bool global_utility = false;
    std::string fault, reason;
  };
  static constexpr size_t kMaxChoices = 300;
  const std::vector<Choice>& choices() const { return choices_; }
  const Stats& stats() const { return stats_; }
  const CoarseQuery& lastQuery() const { return last_query_; }
  const CoarseDecision& lastDecision() const { return last_; }
  nlohmann::json report() const;

 private:
  std::shared_ptr<Reasoner> reasoner_;
  std::shared_ptr<const CommonsensePriors> priors_;
  Instruction instruction_;
  ReasoningConfig cfg_;
  std::vector<RegionSummary> regions_;
  std::map<int, RegionSemantics> semantics_;
  std::vector<int> history_;
  std::map<int, int> visits_;
  int committed_ = -1;
  double committed_t_ = -1e18;
  CoarseQuery last_query_;
  CoarseDecision last_;
  Stats stats_;
  std::vector<Choice> choices_;
  int choices_dropped_ = 0;
};

// {median, p95, count} of a sample (core/timing.hpp percentile; 0s when empty).
nlohmann::json latencySummary(const std::vector<double>& ms);

}  // namespace ussnav
