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

void printCollision(double t, const Vec3& at, bool approaching, const std::vector<Vec3>& path, const RollingGrid& grid,
                    const GroundTruthGrid& truth) {
  std::fprintf(stderr, "[t=%.1f] COLLISION at (%.2f %.2f %.2f) approaching=%d path:", t, at.x(), at.y(), at.z(),
               int(approaching));
  for (const Vec3& q : path) std::fprintf(stderr, " (%.2f %.2f %.2f)", q.x(), q.y(), q.z());
  std::fprintf(stderr, "\n");
  const Vec3i c = grid.keyOf(at);
  for (int dz = -3; dz <= 3; dz += 3) {
    std::fprintf(stderr, "  z%+d:\n", dz);
    for (int dy = 4; dy >= -4; --dy) {
      std::fprintf(stderr, "   ");
      for (int dx = -4; dx <= 4; ++dx) {
        const VoxelState st = grid.state(c + Vec3i(dx, dy, dz));
        const bool solid = truth.sphereCollides(grid.centerOf(c + Vec3i(dx, dy, dz)), 0.02);
        const char ch = st == VoxelState::Occupied ? (solid ? '#' : 'o')
                        : st == VoxelState::Free   ? (solid ? '!' : '.')
                                                   : (solid ? 'U' : '?');
        std::fprintf(stderr, "%c", ch);
      }
      std::fprintf(stderr, "\n");
    }
  }
}

}  // namespace ussnav
