#pragma once
// The offline reasoner (reasoner.hpp, `builtin`). With P(room | object) from the priors:
//  - a region's room distribution is the mean of its objects' rows mixed with a uniform share
//    (weight 0.5), a corridor's shape (corridorShaped: >= 3:1) counting as one more object whose
//    row is "hallway"; its label the most likely room, its confidence 1 - exp(-n / 2) for n
//    pieces of evidence (objects with a prior, the shape); none: unknown;
//  - the target's affinity A(room) = max over the instruction's targets of P(room | target),
//    scaled to max 1; a room constraint multiplies other rooms by 0.05;
//  - a region's own chance s_self = conf * sum_k P(k | region) A(k) + (1 - conf) * mean_k A(k)
//    over its objects only (a corridor without objects with a prior counts as a hallway at
//    confidence 0.3), and 1 when it already holds an object matching a target; 0.5 everywhere when
//    no target has a prior;
//  - frontiers look into unknown space: half of their gain is taken to lie in the room next
//    door, whose type follows the room-adjacency prior from the region's type: s_next = conf *
//    sum_k P(k | region) sum_j adj(k, j) A(j) / sum_j adj(k, j) + (1 - conf) * mean; the chance
//    is s = (1 - f) s_self + f s_next with f = 0.5 * frontier gain / gain (a hallway scores high
//    for a bed, a kitchen does not); objects seen beyond the region (RegionState::beyond, in a
//    room not entered yet) are the next room's own evidence: s_next <- conf_b * sum_k
//    P(k | beyond) A(k) + (1 - conf_b) * s_next, and 1 when one of them matches a target;
//  - the choice maximises (s + 0.02) * best_utility, the region's best target gain / cost (the
//    frontier planner's own criterion), the region chosen last (else the current one) x 1.2
//    while it has targets;
//  - semantics too weak to act on (paper Sec. V-B: "the system reverts to a global utility
//    maximization strategy"): unless that choice's chance is at least min_chance_ratio (1.5)
//    times, and min_chance_gap (0.1) more than, the chance of the region holding the best
//    gain / cost target (ChanceRule), that region is chosen instead
//    (CoarseDecision::global_utility), so bare or alike regions are explored as the frontier
//    planner would, commitment bonus and all chance noise aside.

#include <functional>
#include <memory>

#include "ussnav/reasoning/reasoner.hpp"

namespace ussnav {

// When a region's chance stands out enough to act on: at least min_ratio times, and min_gap
// more than, the chance of the best gain / cost target's region (reasoning.min_chance_ratio,
// reasoning.min_chance_gap). min_ratio 0: always.
struct ChanceRule {
  double min_ratio = 1.5;
  double min_gap = 0.1;
  bool standsOut(double chance, double global_chance) const {
    return min_ratio <= 0.0 || (chance >= min_ratio * global_chance && chance - global_chance >= min_gap);
  }
};
inline ChanceRule chanceRule(const ReasoningConfig& cfg) { return {cfg.min_chance_ratio, cfg.min_chance_gap}; }

class BuiltinReasoner : public Reasoner {
 public:
  explicit BuiltinReasoner(std::shared_ptr<const CommonsensePriors> priors, ChanceRule rule = {});
  std::string name() const override { return "builtin"; }
  RegionSemantics labelRegion(const RegionSummary& region) override;
  CoarseDecision chooseRegion(const CoarseQuery& query) override;

  // P(room type) of a set of object labels (size priors.rooms()): the mean of the rows of its
  // kinds, each label once however often it occurs, a corridor's shape counting as one more
  // kind that says "hallway"; `known` = the evidence: kinds with a prior (+ 1 shape).
  std::vector<double> roomDistribution(const std::vector<std::string>& labels, double* known = nullptr,
                                       bool corridor_shaped = false) const;
  // What a region's objects (or a corridor's shape) say about its room type: P(type) (size
  // priors.rooms()) and the confidence conf in it (0: nothing known, s falls back to the mean).
  struct RoomBelief {
    std::vector<double> p;
    double confidence = 0.0;
  };
  RoomBelief roomBelief(const RegionState& r) const;
  // The chance s above for one region of the query; the second form takes the region's room
  // belief from elsewhere (the evaluation's oracle-labels reasoner: its true type at this belief's confidence).
  double targetChance(const CoarseQuery& q, const RegionState& r) const;
  double targetChance(const CoarseQuery& q, const RegionState& r, const RoomBelief& belief) const;
  const CommonsensePriors& priors() const { return *priors_; }

 private:
  std::shared_ptr<const CommonsensePriors> priors_;
  ChanceRule rule_;
  int hallway_ = -1;  // the priors' "hallway" room type, -1 when they have none
};

// The decision rule above with any chance function s(region): max (s + 0.02) * best_utility,
// the committed region x 1.2, then the global-utility region unless the choice's s stands out
// (`rule`); fault "no_frontiers" when no region has a reachable target. Shared with the
// evaluation's oracle (eval/region_oracle.hpp), so the two differ only in s.
CoarseDecision chooseByChance(const CoarseQuery& q, const std::function<double(const RegionState&)>& chance,
                              ChanceRule rule = {});
// s = (1 - f) s_self + f s_next with f = 0.5 * frontier gain / gain (s_self without frontiers).
double blendChance(const RegionState& r, double s_self, double s_next);

}  // namespace ussnav
