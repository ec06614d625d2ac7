#include "ussnav/exploration/viewpoint.hpp"

#include <algorithm>
#include <cmath>

namespace ussnav {

namespace {

// Range and vertical field of view: cheap, tried before the ray cast.
bool inRangeAndVfov(const Vec3& d, const ExplorationConfig& cfg) {
  return d.norm() <= cfg.sensor_range &&
         std::abs(std::atan2(d.z(), std::hypot(d.x(), d.y()))) <= 0.5 * deg2rad(cfg.sensor_vfov_deg);
}

// The yaw-independent part of visibility: range, vertical field of view, line of sight.
// Sets `azimuth` of the cell seen from p.
bool seenIgnoringYaw(const RollingGrid& grid, const Vec3& p, const Vec3i& key, const ExplorationConfig& cfg,
                     double& azimuth) {
  const Vec3 c = grid.centerOf(key);
  const Vec3 d = c - p;
  if (!inRangeAndVfov(d, cfg) || !grid.lineOfSight(p, c, /*unknown_blocks=*/true)) return false;
  azimuth = std::atan2(d.y(), d.x());
  return true;
}

bool inHfov(double azimuth, double yaw, const ExplorationConfig& cfg) {
  return std::abs(wrapAngle(azimuth - yaw)) <= 0.5 * deg2rad(cfg.sensor_hfov_deg);
}

}  // namespace

bool cellVisible(const RollingGrid& grid, const Vec3& position, double yaw, const Vec3i& key,
                 const ExplorationConfig& cfg) {
  double az = 0.0;
  return seenIgnoringYaw(grid, position, key, cfg, az) && inHfov(az, yaw, cfg);
}

bool viewpointSafe(const RollingGrid& grid, const Vec3& p, const ExplorationConfig& cfg) {
  const Vec3i k = grid.keyOf(p);
  return grid.inWindow(k) && grid.stateFast(k) == VoxelState::Free &&
         !grid.isInflatedOccupied(p, cfg.viewpoint_clearance, /*unknown_unsafe=*/true);
}

double visibleUnknownVolume(const RollingGrid& grid, const Vec3& position, double yaw,
                            const ExplorationConfig& cfg) {
  const double hfov = deg2rad(cfg.sensor_hfov_deg), vfov = deg2rad(cfg.sensor_vfov_deg);
  const int n_az = std::max(1, int(std::ceil(cfg.sensor_hfov_deg / 4.0)));
  const int n_el = std::max(1, int(std::ceil(cfg.sensor_vfov_deg / 5.0)));
  const double d_az = hfov / n_az, d_el = vfov / n_el;
  const double dr = grid.resolution();
  double volume = 0.0;
  for (int j = 0; j < n_el; ++j) {
    const double el = -0.5 * vfov + (j + 0.5) * d_el;
    const double d_omega = d_az * d_el * std::cos(el);
    for (int i = 0; i < n_az; ++i) {
      const double az = yaw - 0.5 * hfov + (i + 0.5) * d_az;
      const Vec3 dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
      for (double r = 0.5 * dr; r < cfg.sensor_range; r += dr) {
        const Vec3 p = position + r * dir;
        const Vec3i k = grid.keyOf(p);
        if (!grid.inWindow(k)) break;
        const VoxelState s = grid.stateFast(k);
        if (s == VoxelState::Occupied) break;
        if (s != VoxelState::Unknown) continue;
        const double z = grid.centerOf(k).z();
        if (z >= cfg.band_z_min && z <= cfg.band_z_max) volume += r * r * dr * d_omega;
      }
    }
  }
  return volume;
}

std::vector<Viewpoint> computeViewpoints(const RollingGrid& grid, const std::vector<Vec3i>& cells,
                                         const Vec3& centroid, const ExplorationConfig& cfg) {
  std::vector<Viewpoint> out;
  std::vector<double> az;
  std::vector<const Vec3i*> near;
  az.reserve(cells.size());
  near.reserve(cells.size());
  const int n_phi = std::max(1, int(std::lround(360.0 / cfg.viewpoint_dphi_deg)));
  const int n_yaw = std::max(1, int(std::lround(360.0 / cfg.yaw_step_deg)));
  for (int ring = 0; ring < cfg.viewpoint_rings; ++ring) {
    const double r = cfg.viewpoint_rings == 1
                         ? cfg.viewpoint_r_min
                         : cfg.viewpoint_r_min + ring * (cfg.viewpoint_r_max - cfg.viewpoint_r_min) /
                                                     (cfg.viewpoint_rings - 1);
    for (int k = 0; k < n_phi; ++k) {
      const double phi = 2 * kPi * k / n_phi;
      const Vec3 p(centroid.x() + r * std::cos(phi), centroid.y() + r * std::sin(phi), cfg.viewpoint_height);
      if (!viewpointSafe(grid, p, cfg)) continue;
      // Ray casts dominate: only for cells in range, and not once the position cannot reach
      // min_viewpoint_gain (the result is the same).
      near.clear();
      for (const Vec3i& c : cells)
        if (inRangeAndVfov(grid.centerOf(c) - p, cfg)) near.push_back(&c);
      az.clear();
      for (size_t i = 0; i < near.size(); ++i) {
        if (int(az.size() + near.size() - i) < cfg.min_viewpoint_gain) break;
        const Vec3 c = grid.centerOf(*near[i]);
        if (grid.lineOfSight(p, c, /*unknown_blocks=*/true)) az.push_back(std::atan2(c.y() - p.y(), c.x() - p.x()));
      }
      if (int(az.size()) < cfg.min_viewpoint_gain || az.empty()) continue;
      Viewpoint best{p, 0.0, -1};
      for (int y = 0; y < n_yaw; ++y) {
        const double yaw = wrapAngle(2 * kPi * y / n_yaw);
        int gain = 0;
        for (double a : az) gain += inHfov(a, yaw, cfg);
        if (gain > best.gain) best = {p, yaw, gain};
      }
      if (best.gain >= cfg.min_viewpoint_gain) out.push_back(best);
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Viewpoint& a, const Viewpoint& b) { return a.gain > b.gain; });
  if (int(out.size()) > cfg.max_viewpoints) out.resize(size_t(cfg.max_viewpoints));
  return out;
}

}  // namespace ussnav
