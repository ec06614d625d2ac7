#include "ussnav/episode/exploration_targets.hpp"

#include <cmath>
#include <cstdio>

#include "ussnav/exploration/viewpoint.hpp"

namespace ussnav {

std::optional<Viewpoint> nodeFacing(const ConnectivityGraph& graph, const Vec3& c, double z, int gain) {
  const int n = graph.size() > 0 ? graph.nearestNode(c) : -1;
  if (n < 0) return std::nullopt;
  Viewpoint v;
  v.position = graph.node(n).center;
  v.position.z() = z;
  v.yaw = std::atan2(c.y() - v.position.y(), c.x() - v.position.x());
  v.gain = gain;
  return v;
}

std::vector<ExplorationTarget> collectTargets(const FrontierFinder& frontiers, const std::vector<UnseenPatch>& patches,
                                              TargetMemory& memory, double t, const ConnectivityGraph& graph,
                                              const RollingGrid& grid, const ExplorationConfig& cfg, bool close_look,
                                              double flight_z, bool debug) {
  std::vector<ExplorationTarget> targets;
  for (const Frontier& fr : frontiers.frontiers()) {
    if (memory.skipped(fr.centroid, t)) {
      if (debug)
        std::fprintf(stderr, "  skip frontier (%.2f %.2f) %zu cells: blacklisted\n", fr.centroid.x(), fr.centroid.y(),
                     fr.cells.size());
      continue;
    }
    ExplorationTarget tg;
    tg.kind = TargetKind::Frontier;
    tg.source_id = fr.id;
    tg.centroid = fr.centroid;
    tg.viewpoints = fr.viewpoints;
    if (const Vec3* from = close_look ? memory.lookedFrom(fr.centroid) : nullptr) {
      tg.viewpoints.clear();
      const std::optional<Viewpoint> v = nodeFacing(graph, fr.centroid, flight_z, int(fr.cells.size()));
      if (!v) continue;
      if ((v->position.head<2>() - from->head<2>()).norm() < 0.5) {
        memory.skipForGood(fr.centroid);
        continue;
      }
      tg.viewpoints.push_back(*v);
    }
    if (tg.viewpoints.empty()) {
      const std::optional<Viewpoint> v = nodeFacing(graph, fr.centroid, flight_z, int(fr.cells.size() / 2));
      if (!v) continue;
      const double away = (v->position.head<2>() - fr.centroid.head<2>()).norm();
      if (away > 3.0) {
        if (debug)
          std::fprintf(stderr, "  skip frontier (%.2f %.2f) %zu cells: no viewpoint, nearest node %.1f m away\n",
                       fr.centroid.x(), fr.centroid.y(), fr.cells.size(), away);
        continue;
      }
      tg.viewpoints.push_back(*v);
    }
    tg.gain = tg.viewpoints.front().gain * 1.0;
    if (cfg.unknown_volume_weight > 0.0)
      tg.gain += cfg.unknown_volume_weight *
                 visibleUnknownVolume(grid, tg.viewpoints.front().position, tg.viewpoints.front().yaw, cfg);
    targets.push_back(std::move(tg));
  }
  for (const UnseenPatch& p : patches) {
    if (p.viewpoints.empty() || memory.skipped(p.centroid, t)) continue;
    ExplorationTarget tg;
    tg.kind = TargetKind::Unseen;
    tg.source_id = p.id;
    tg.centroid = p.centroid;
    tg.viewpoints = p.viewpoints;
    tg.gain = p.viewpoints.front().gain * 4.0;
    targets.push_back(std::move(tg));
  }
  return targets;
}

}  // namespace ussnav
