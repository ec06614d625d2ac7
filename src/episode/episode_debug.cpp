#include "ussnav/episode/episode_debug.hpp"

#include <cstdio>
#include <string>

namespace ussnav {

void printPlan(const ExplorationTarget& tg, const Viewpoint& vp, const std::vector<Vec3>& path,
               const PlanChoice& choice, const CoarseDecider* decider, const std::vector<ExplorationTarget>& targets) {
  std::fprintf(stderr, "  plan -> %s (%.2f %.2f) vp (%.2f %.2f) path", toString(tg.kind), tg.centroid.x(),
               tg.centroid.y(), vp.position.x(), vp.position.y());
  for (const Vec3& q : path) std::fprintf(stderr, " (%.2f %.2f %.2f)", q.x(), q.y(), q.z());
  std::fprintf(stderr, "\n    gain %.0f region %d: %s%s%s\n", tg.gain, tg.region, choice.note.c_str(),
               decider ? " | " : "", decider ? decider->lastDecision().reason.c_str() : "");
  if (decider)
    for (const auto& sc : decider->lastDecision().scores)
      if (const RegionState* r = decider->lastQuery().find(sc.region)) {
        std::string seen;
        for (const auto& l : r->objects) seen += " " + l;
        if (!r->beyond.empty()) seen += " | beyond:";
        for (const auto& l : r->beyond) seen += " " + l;
        std::fprintf(stderr, "      region %d (%s%s): chance %.3f value %.1f utility %.1f frontier gain %.0f of %.0f,%s\n",
                     sc.region, r->label.empty() ? "unlabelled" : r->label.c_str(), r->corridor_shaped ? ", corridor" : "",
                     sc.chance, sc.value, r->best_utility, r->frontier_gain, r->gain, seen.c_str());
      }
  for (const ExplorationTarget& o : targets)
    std::fprintf(stderr, "      %s (%.2f %.2f) gain %.0f region %d\n", toString(o.kind), o.centroid.x(), o.centroid.y(),
                 o.gain, o.region);
}

}  // namespace ussnav
