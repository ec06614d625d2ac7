#include "ussnav/episode/approach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ussnav {

double distanceToBox(const Aabb& box, const Vec3& p) {
  const Vec3 d = (box.min - p).cwiseMax(p - box.max).cwiseMax(Vec3::Zero());
  return d.norm();
}

// The first blocking voxel meets the box when it overlaps the box grown by kTouch (rounding).
bool seesBox(const OccupancyMap& map, const Vec3& p, const Vec3& c, const Aabb& box, bool unknown_blocks) {
  constexpr double kTouch = 0.01;
  const RayHit hit = castRay(map, p, c, unknown_blocks);
  if (!hit.blocked) return true;
  if (hit.hit_state != VoxelState::Occupied) return false;  // the object's surface is what was seen of it
  const Vec3 inside = hit.point + (c - p).normalized() * (1e-3 * map.resolution());
  const Vec3 lo = map.keyOf(inside).cast<double>() * map.resolution();  // the blocking voxel's corner
  const Vec3 hi = lo + Vec3::Constant(map.resolution());
  return (lo.array() <= box.max.array() + kTouch).all() && (hi.array() >= box.min.array() - kTouch).all();
}

namespace {
constexpr double kSightCorridor = 0.75;  // m, see transitNode
}  // namespace

int transitNode(const ConnectivityGraph& graph, const OccupancyMap& map, const Aabb& box, const Vec3& centroid,
                double flight_z, double radius, const std::vector<Vec3>& avoid, const Vec3* seen_from) {
  if (graph.size() == 0) return -1;
  const auto avoided = [&](int n) {
    return std::any_of(avoid.begin(), avoid.end(),
                       [&](const Vec3& a) { return (graph.node(n).center - a).head<2>().norm() < 1.0; });
  };
  const Vec3 c = box.center();
  int best = -1, nearest = -1, seen_side = -1;
  double best_d = std::numeric_limits<double>::infinity(), nearest_d = best_d, seen_side_d = best_d;
  for (const int n : graph.nodesWithin(centroid, radius)) {
    if (avoided(n)) continue;
    const Vec3 at(graph.node(n).center.x(), graph.node(n).center.y(), flight_z);
    const double d = (at - centroid).norm();
    if (d < nearest_d) nearest = n, nearest_d = d;
    if (d < best_d && seesBox(map, at, c, box, true)) best = n, best_d = d;
    // Along the line of sight it was seen along (in plan): space the camera looked through.
    if (seen_from) {
      const Vec2 a = seen_from->head<2>(), ab = centroid.head<2>() - a, p = graph.node(n).center.head<2>();
      const double t = ab.squaredNorm() > 1e-12 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      if ((p - (a + t * ab)).norm() <= kSightCorridor && d < seen_side_d) seen_side = n, seen_side_d = d;
    }
  }
  if (best >= 0) return best;
  if (seen_side >= 0) return seen_side;
  if (!avoid.empty() && nearest >= 0) return nearest;
  return graph.nearestNode(centroid);
}

std::vector<ApproachPose> approachPoses(const OccupancyMap& map, const GraphDistances& from_uav, const Aabb& box,
                                        double flight_z, const Config& cfg, int max_poses) {
  std::vector<ApproachPose> out;
  if (box.empty()) return out;
  const EpisodeConfig& ep = cfg.episode;
  const double reach = ep.found_radius - ep.found_margin;
  const double half_v = deg2rad(0.5 * cfg.sim.camera.vfov_deg - 5.0);
  const Vec3 c = box.center();
  const Vec3 half = 0.5 * box.size();
  auto collect = [&](double z, double clearance) {
    if (z < clearance + 0.2) return;
    for (int a = 0; a < 24; ++a) {
      const double phi = a * 2.0 * kPi / 24.0;
      const Vec2 dir(std::cos(phi), std::sin(phi));
      // Distance from the box centre to its side along dir.
      const double tx = std::abs(dir.x()) > 1e-9 ? half.x() / std::abs(dir.x()) : 1e9;
      const double ty = std::abs(dir.y()) > 1e-9 ? half.y() / std::abs(dir.y()) : 1e9;
      const double side = std::min(tx, ty);
      for (double gap : {0.2, 0.4, 0.6, 0.8}) {
        const Vec2 xy = c.head<2>() + dir * (side + gap);
        const Vec3 p(xy.x(), xy.y(), z);
        if (distanceToBox(box, p) > reach) continue;
        if (!map.inWindow(map.keyOf(p)) || !isSafe(map, p, clearance, true)) continue;
        const Vec3 to = c - p;
        const double horiz = to.head<2>().norm();
        const double zt = std::clamp(p.z(), box.min.z(), box.max.z());
        if (std::atan2(std::abs(p.z() - zt), std::max(horiz, 0.05)) > half_v) continue;  // the box centre in view
        if (!seesBox(map, p, c, box, false)) continue;
        const double cost = from_uav.toPoint(p);
        if (!std::isfinite(cost)) continue;
        out.push_back(ApproachPose{p, std::atan2(to.y(), to.x()), cost});
      }
    }
  };
  // At flight height or lower first; above it only for what no such pose sees (a TV hung high
  // on a wall). Within each, the flight paths' clearance, then the narrower fallback when no
  // pose keeps it (small rooms).
  const std::vector<double> at_or_below = {0.0, -0.3, -0.6}, above = {kApproachAbove};
  for (const std::vector<double>* dzs : {&at_or_below, &above}) {
    for (const double clearance : {ep.clearance, cfg.sim.uav.radius + 0.1}) {
      for (const double dz : *dzs) collect(flight_z + dz, clearance);
      if (!out.empty()) break;
    }
    if (!out.empty()) break;
  }
  std::stable_sort(out.begin(), out.end(), [](const ApproachPose& a, const ApproachPose& b) { return a.cost_m < b.cost_m; });
  if (int(out.size()) > max_poses) out.resize(size_t(max_poses));
  return out;
}

}  // namespace ussnav
