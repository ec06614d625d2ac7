// The offline commonsense reasoner (see builtin_reasoner.hpp).

#include "ussnav/reasoning/builtin_reasoner.hpp"

#include "english.hpp"
#include "ussnav/core/timing.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace ussnav {
namespace {

constexpr double kUniformWeight = 0.5;  // mixed into a region's room distribution
constexpr double kOtherRoom = 0.05;     // affinity factor of rooms that break a room constraint
constexpr double kStay = 1.2;           // value factor of the region chosen last (else the current one)
// Weight of a corridor's shape as evidence for "hallway", in objects: a corridor with a plant
// and a printer is still a hallway, a bathroom with a toilet, a sink and a mirror is not.
constexpr double kShapeVotes = 1.0;
constexpr double kShapeOnly = 0.3;  // confidence of a hallway known from its shape alone (chance)
// Share of a frontier's gain that lies in the next room rather than in more of the same one.
constexpr double kBeyond = 0.5;

// Whether one of `labels` is one of the targets (the same test as a found object's).
bool namesTarget(const TextEncoder& enc, const std::vector<std::string>& labels, const std::vector<std::string>& targets) {
  for (const auto& o : labels)
    for (const auto& t : targets)
      if (enc.similarity(o, t) >= 0.85) return true;
  return false;
}

// sum_k P(k) A(k): the target's affinity expected under a room distribution.
double expectedAffinity(const std::vector<double>& P, const std::vector<double>& A) {
  double s = 0.0;
  for (size_t k = 0; k < P.size(); ++k) s += P[k] * A[k];
  return s;
}

}  // namespace

BuiltinReasoner::BuiltinReasoner(std::shared_ptr<const CommonsensePriors> priors, ChanceRule rule)
    : priors_(std::move(priors)), rule_(rule), hallway_(priors_->roomIndex("hallway")) {}

std::vector<double> BuiltinReasoner::roomDistribution(const std::vector<std::string>& labels, double* known,
                                                      bool corridor_shaped) const {
  const size_t R = priors_->rooms().size();
  std::vector<double> p(R, 0.0);
  double n = 0.0;
  // Each kind of object once: six chairs round a table say "chair" no louder than one does
  // (counted six times they made dining rooms and meeting rooms living rooms; docs/eval.md,
  // session 49).
  const std::set<std::string> kinds(labels.begin(), labels.end());
  for (const auto& l : kinds) {
    const auto row = priors_->roomsGivenObject(l);
    if (row.empty()) continue;
    for (size_t k = 0; k < R; ++k) p[k] += row[k];
    n += 1.0;
  }
  if (corridor_shaped && hallway_ >= 0) {
    p[size_t(hallway_)] += kShapeVotes;
    n += kShapeVotes;
  }
  if (known) *known = n;
  double s = 0.0;
  for (size_t k = 0; k < R; ++k) {
    p[k] = (n > 0.0 ? p[k] / n : 0.0) + kUniformWeight / double(R);
    s += p[k];
  }
  for (double& x : p) x /= s;
  return p;
}

RegionSemantics BuiltinReasoner::labelRegion(const RegionSummary& region) {
  RegionSemantics s;
  s.source = name();
  s.key = contentKey(region);
  std::vector<std::string> labels;
  for (const ObjectBrief& o : region.objects) labels.push_back(o.label);
  double known = 0.0;
  s.room_probs = roomDistribution(labels, &known, corridorShaped(region));
  if (known > 0.0) {
    const size_t k = size_t(std::max_element(s.room_probs.begin(), s.room_probs.end()) - s.room_probs.begin());
    s.label = priors_->rooms()[k].name;
    s.confidence = (1.0 - std::exp(-known / 2.0)) * s.room_probs[k];
  }
  // Description: "A bedroom (about 4.1 x 3.0 m) with a bed, a wardrobe and 2 more objects."
  std::map<std::string, int> count;
  for (const auto& l : labels) ++count[l];
  std::vector<std::pair<int, std::string>> top;
  for (const auto& [l, c] : count) top.push_back({c, l});
  std::stable_sort(top.begin(), top.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::ostringstream d;
  const Vec3 ext = region.box_max - region.box_min;
  d.setf(std::ios::fixed);
  d.precision(1);
  d << english::capitalised(s.label.empty() ? std::string("an unidentified area") : english::withArticle(s.label)) << " (about " << ext.x() + 1.0 << " x "
    << ext.y() + 1.0 << " m)";
  if (top.empty()) d << " with no objects seen yet";
  for (size_t i = 0; i < top.size() && i < 3; ++i)
    d << (i == 0 ? " with " : i + 1 == std::min<size_t>(top.size(), 3) && top.size() <= 3 ? " and " : ", ")
      << (top[i].first > 1 ? english::counted(top[i].first, top[i].second) : english::withArticle(top[i].second));
  if (top.size() > 3) d << " and " << top.size() - 3 << " more kinds of object";
  d << ".";
  s.description = d.str();
  return s;
}

BuiltinReasoner::RoomBelief BuiltinReasoner::roomBelief(const RegionState& r) const {
  // The chance weighs objects only; a corridor's shape counts when no object has a prior (a
  // hallway at confidence kShapeOnly). Counting the shape next to objects names corridors
  // better (docs/eval.md) but moved flights both ways and lost SPL on two suites.
  RoomBelief b;
  double known = 0.0;
  b.p = roomDistribution(r.objects, &known);
  b.confidence = 1.0 - std::exp(-known / 2.0);
  if (known == 0.0 && r.corridor_shaped && hallway_ >= 0) {
    std::fill(b.p.begin(), b.p.end(), 0.0);
    b.p[size_t(hallway_)] = 1.0;
    b.confidence = kShapeOnly;
  }
  return b;
}

double BuiltinReasoner::targetChance(const CoarseQuery& q, const RegionState& r) const {
  return targetChance(q, r, roomBelief(r));
}

double BuiltinReasoner::targetChance(const CoarseQuery& q, const RegionState& r, const RoomBelief& belief) const {
  const size_t R = priors_->rooms().size();
  const TextEncoder& enc = priors_->encoder();
  if (namesTarget(enc, r.objects, q.instruction.targets)) return 1.0;
  // Target affinity per room.
  std::vector<double> A(R, 0.0);
  bool any = false;
  for (const auto& t : q.instruction.targets) {
    const auto row = priors_->roomsGivenObject(t);
    if (row.empty()) continue;
    any = true;
    for (size_t k = 0; k < R; ++k) A[k] = std::max(A[k], row[k]);
  }
  if (!any) std::fill(A.begin(), A.end(), 1.0);  // no prior: every room alike (chance 0.5 below)
  const int room = q.instruction.room.empty() ? -1 : priors_->roomIndex(q.instruction.room);
  if (room >= 0)
    for (size_t k = 0; k < R; ++k)
      if (int(k) != room) A[k] *= kOtherRoom;
  const double amax = *std::max_element(A.begin(), A.end());
  if (amax <= 0.0) return 0.0;
  if (!any && room < 0) return 0.5;  // nothing to tell the regions apart but a matching object
  double mean = 0.0;
  for (double& a : A) mean += (a /= amax) / double(R);
  const std::vector<double>& P = belief.p;
  const double conf = belief.confidence;
  if (P.size() != R) return mean;
  const double s_self = conf * expectedAffinity(P, A) + (1.0 - conf) * mean;
  if (kBeyond <= 0.0 || r.gain <= 0.0 || r.frontier_gain <= 0.0) return s_self;
  // Frontiers look into unknown space: more of this room, or the room next door, whose type
  // follows the adjacency prior from this region's type.
  double s_next = 0.0;
  for (size_t k = 0; k < R; ++k) {
    if (P[k] <= 0.0) continue;
    double norm = 0.0, s = 0.0;
    for (size_t j = 0; j < R; ++j) {
      const double w = priors_->adjacency(int(k), int(j));
      norm += w;
      s += w * A[j];
    }
    if (norm > 0.0) s_next += P[k] * s / norm;
  }
  s_next = conf * s_next + (1.0 - conf) * mean;
  // Objects seen beyond the region (through a door) are that next room's own evidence.
  if (namesTarget(enc, r.beyond, q.instruction.targets)) return blendChance(r, s_self, 1.0);
  if (!r.beyond.empty()) {
    double seen = 0.0;
    const auto B = roomDistribution(r.beyond, &seen);
    const double conf_b = 1.0 - std::exp(-seen / 2.0);
    s_next = conf_b * expectedAffinity(B, A) + (1.0 - conf_b) * s_next;
  }
  return blendChance(r, s_self, s_next);
}

double blendChance(const RegionState& r, double s_self, double s_next) {
  if (kBeyond <= 0.0 || r.gain <= 0.0 || r.frontier_gain <= 0.0) return s_self;
  const double f = kBeyond * std::clamp(r.frontier_gain / r.gain, 0.0, 1.0);
  return (1.0 - f) * s_self + f * s_next;
}

CoarseDecision BuiltinReasoner::chooseRegion(const CoarseQuery& q) {
  return chooseByChance(q, [&](const RegionState& r) { return targetChance(q, r); }, rule_);
}

CoarseDecision chooseByChance(const CoarseQuery& q, const std::function<double(const RegionState&)>& chance,
                              ChanceRule rule) {
  const Stopwatch sw;
  CoarseDecision d;
  double best = -1.0;
  double best_s = 0.0;
  // Commitment: the region chosen last keeps a bonus while it has frontiers (values change a
  // little every frame as the UAV moves; without it two far regions can win in turn and the
  // UAV flies back and forth); before any choice, or once it is done, the current region.
  const RegionState* last = q.find(q.last_choice);
  const int stay = last && last->frontiers > 0 && last->cost_s >= 0.0 ? q.last_choice : q.current_region;
  const RegionState* global = nullptr;  // the region of the best gain / cost target
  double global_s = 0.0;
  for (const RegionState& r : q.regions) {
    if (r.frontiers <= 0 || r.cost_s < 0.0) continue;
    const double s = chance(r);
    double v = (s + 0.02) * r.best_utility;
    if (!global || r.best_utility > global->best_utility) global = &r, global_s = s;
    if (r.id == stay) v *= kStay;
    d.scores.push_back({r.id, s, v});
    if (v > best) best = v, d.region = r.id, best_s = s;
  }
  // Semantics too weak to act on: the global-utility choice. Near the floor (nothing in sight
  // says much about the goal) chances differ by noise, so the ratio alone is not enough.
  if (global && global->id != d.region && !rule.standsOut(best_s, global_s)) {
    d.region = global->id, best_s = global_s;
    d.global_utility = true;
  }
  if (d.region < 0) {
    d.fault = "no_frontiers";
    d.reason = "no region has anything left to explore";
  } else {
    const RegionState* r = q.find(d.region);
    std::ostringstream why;
    why.setf(std::ios::fixed);
    why.precision(2);
    why << "region " << d.region << " (" << (r->label.empty() ? "unlabelled" : r->label) << "): chance " << best_s
        << ", " << r->frontiers << " targets, " << r->cost_s << " s away"
        << (d.global_utility ? " (best gain / cost: no region's chance stands out)" : "");
    d.reason = why.str();
  }
  d.latency_ms = sw.ms();
  return d;
}

}  // namespace ussnav
