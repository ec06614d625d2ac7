#include "ussnav/exploration/camera_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ussnav/core/error.hpp"

namespace ussnav {

CameraCoverage::CameraCoverage(const ExplorationConfig& cfg, double flight_z)
    : cfg_(cfg), res_(cfg.seen_resolution), z_(flight_z) {
  if (!(res_ > 0.0) || !std::isfinite(res_))
    throw InputError("exploration", "seen_resolution", "must be a positive number of metres");
  if (!(cfg.seen_range > 0.0)) throw InputError("exploration", "seen_range", "must be positive");
  if (cfg.seen_pixel_stride < 1) throw InputError("exploration", "seen_pixel_stride", "must be at least 1");
  if (!std::isfinite(flight_z)) throw InputError("exploration", "flight height", "must be finite");
}

uint8_t CameraCoverage::flags(const Vec2i& c) const {
  const auto it = cells_.find(pack(c));
  return it == cells_.end() ? 0 : it->second;
}

void CameraCoverage::set(const Vec2i& c, uint8_t f) {
  uint8_t& v = cells_[pack(c)];
  const uint8_t before = v;
  v |= f;
  if (!(before & kKnown) && (v & kKnown)) ++known_;
  const bool was = (before & kKnown) && (before & kSeen), now = (v & kKnown) && (v & kSeen);
  if (!was && now) ++seen_known_;
}

Vec2i CameraCoverage::cellOf(const Vec2& p) const {
  return Vec2i(int(std::floor(p.x() / res_)), int(std::floor(p.y() / res_)));
}

Vec3 CameraCoverage::centerOf(const Vec2i& c) const {
  return Vec3((c.x() + 0.5) * res_, (c.y() + 0.5) * res_, z_);
}

void CameraCoverage::updateKnown(const RollingGrid& grid) {
  const double r = grid.resolution();
  const int kz = int(std::floor(z_ / r));
  const Vec3i lo = grid.minKey(), dims = grid.dims();
  if (kz < lo.z() || kz >= lo.z() + dims.z()) return;
  // A 2-D cell is known when the voxel at its centre is Free at flight height.
  const Vec2 wlo(lo.x() * r, lo.y() * r), whi((lo.x() + dims.x()) * r, (lo.y() + dims.y()) * r);
  const Vec2i clo = cellOf(wlo), chi = cellOf(whi);
  for (int cy = clo.y(); cy <= chi.y(); ++cy)
    for (int cx = clo.x(); cx <= chi.x(); ++cx) {
      const Vec2i c(cx, cy);
      const Vec3 p = centerOf(c);
      const Vec3i k(int(std::floor(p.x() / r)), int(std::floor(p.y() / r)), kz);
      if (!grid.inWindow(k)) continue;
      if (grid.state(k) == VoxelState::Free && !(flags(c) & kKnown)) set(c, kKnown);
    }
}

void CameraCoverage::updateSeen(const DepthFrame& f) {
  const Intrinsics& K = f.K;
  if (K.width <= 0 || K.height <= 0 || f.depth.size() != size_t(K.width) * size_t(K.height)) return;
  const Vec3 o = f.T_world_camera.translation();
  const int s = cfg_.seen_pixel_stride;
  std::unordered_set<uint64_t> marked;  // cells marked this frame (skip repeated walks)
  for (int v = s / 2; v < K.height; v += s)
    for (int u = s / 2; u < K.width; u += s) {
      float d = f.depth[size_t(v) * K.width + u];
      if (std::isnan(d) || d < 0) continue;  // invalid or too close: the pixel saw nothing (frame.hpp)
      double depth = (std::isfinite(d) && d > 0) ? double(d) : f.max_range;
      const Vec3 ray_c((u + 0.5 - K.cx) / K.fx, (v + 0.5 - K.cy) / K.fy, 1.0);
      const Vec3 dir = f.T_world_camera.linear() * ray_c;  // z-depth 1 along the optical axis
      const bool hit = std::isfinite(d) && d > 0;
      Vec3 end = o + dir * depth;
      const double len = (end - o).head<2>().norm();
      if (len > cfg_.seen_range) end = o + (end - o) * (cfg_.seen_range / len);
      // Walk the 2-D cells from the camera to the end (half-cell steps). A cell counts as seen
      // where the ray runs low enough to meet what stands on the floor there (at most
      // flight height - seen_below); the cell where the ray ends saw its obstacle.
      const double l = (end - o).head<2>().norm();
      const int steps = std::max(1, int(std::ceil(l / (0.5 * res_))));
      const double z_low = z_ - cfg_.seen_below;
      for (int i = 1; i <= steps; ++i) {
        const Vec3 q = o + (end - o) * (double(i) / steps);
        const bool last = i == steps && hit && len <= cfg_.seen_range;
        if (q.z() > z_low && !last) continue;
        const Vec2i c = cellOf(q.head<2>());
        if (!marked.insert(pack(c)).second) continue;
        set(c, kSeen);
      }
    }
}

void CameraCoverage::abandon(const std::vector<Vec2i>& cells) {
  for (const Vec2i& c : cells) cells_[pack(c)] |= kAbandoned;
}

bool CameraCoverage::losKnown(const Vec2i& a, const Vec2i& b) const {
  const Vec2 pa = centerOf(a).head<2>(), pb = centerOf(b).head<2>();
  const int steps = std::max(1, int(std::ceil((pb - pa).norm() / (0.5 * res_))));
  for (int i = 1; i < steps; ++i) {
    const Vec2i c = cellOf(pa + (pb - pa) * (double(i) / steps));
    if (c == b) break;
    if (!(flags(c) & kKnown)) return false;
  }
  return true;
}

bool CameraCoverage::clear(const Vec2i& c, int rc) const {
  for (int dy = -rc; dy <= rc; ++dy)
    for (int dx = -rc; dx <= rc; ++dx)
      if (dx * dx + dy * dy <= rc * rc && !(flags(Vec2i(c.x() + dx, c.y() + dy)) & kKnown)) return false;
  return true;
}

std::vector<UnseenPatch> CameraCoverage::patches() const {
  // Unseen targets, in a deterministic order.
  std::vector<uint64_t> open;
  for (const auto& [k, f] : cells_)
    if ((f & kKnown) && !(f & kSeen) && !(f & kAbandoned)) open.push_back(k);
  std::sort(open.begin(), open.end(), [](uint64_t a, uint64_t b) {
    const Vec2i ca = unpack(a), cb = unpack(b);
    return ca.y() != cb.y() ? ca.y() < cb.y() : ca.x() < cb.x();
  });
  std::unordered_set<uint64_t> pending(open.begin(), open.end());
  const int tile = std::max(1, int(std::round(cfg_.unseen_patch_size / res_)));
  auto tileOf = [tile](const Vec2i& c) {
    return Vec2i(int(std::floor(double(c.x()) / tile)), int(std::floor(double(c.y()) / tile)));
  };
  std::vector<UnseenPatch> out;
  const int rc = int(std::ceil(cfg_.unseen_clearance / res_));
  const double half_fov = 0.5 * cfg_.sensor_hfov_deg * std::numbers::pi / 180.0;
  for (uint64_t k0 : open) {
    if (!pending.count(k0)) continue;
    const Vec2i t0 = tileOf(unpack(k0));
    UnseenPatch p;
    std::vector<uint64_t> stack{k0};
    pending.erase(k0);
    while (!stack.empty()) {
      const Vec2i c = unpack(stack.back());
      stack.pop_back();
      p.cells.push_back(c);
      const Vec2i nb[4] = {{c.x() + 1, c.y()}, {c.x() - 1, c.y()}, {c.x(), c.y() + 1}, {c.x(), c.y() - 1}};
      for (const Vec2i& n : nb) {
        const uint64_t kn = pack(n);
        if (pending.count(kn) && tileOf(n) == t0) pending.erase(kn), stack.push_back(kn);
      }
    }
    if (int(p.cells.size()) < cfg_.unseen_min_cells) continue;
    std::sort(p.cells.begin(), p.cells.end(),
              [](const Vec2i& a, const Vec2i& b) { return a.y() != b.y() ? a.y() < b.y() : a.x() < b.x(); });
    Vec2 mean = Vec2::Zero();
    for (const Vec2i& c : p.cells) mean += centerOf(c).head<2>();
    mean /= double(p.cells.size());
    p.centroid = Vec3(mean.x(), mean.y(), z_);
    // Viewpoints on three rings, yaw at the centroid. A level camera sees nothing of the floor
    // layer closer than seen_below / tan(vfov / 2): those cells earn no gain.
    const double d0 = cfg_.unseen_view_distance;
    const double near = cfg_.seen_below / std::tan(0.5 * cfg_.sensor_vfov_deg * std::numbers::pi / 180.0);
    for (double r : {d0, 1.5 * d0, 2.0 * d0})
      for (int a = 0; a < 16; ++a) {
        const double phi = a * std::numbers::pi / 8.0;
        const Vec2 pos = mean + r * Vec2(std::cos(phi), std::sin(phi));
        const Vec2i pc = cellOf(pos);
        if (!clear(pc, rc)) continue;
        const double yaw = std::atan2(mean.y() - pos.y(), mean.x() - pos.x());
        int gain = 0;
        for (const Vec2i& c : p.cells) {
          const Vec2 q = centerOf(c).head<2>() - pos;
          const double dist = q.norm();
          if (dist > cfg_.seen_range || dist < near) continue;
          double dphi = std::atan2(q.y(), q.x()) - yaw;
          dphi = std::remainder(dphi, 2.0 * std::numbers::pi);
          if (std::abs(dphi) > half_fov) continue;
          if (losKnown(pc, c)) ++gain;
        }
        if (gain < std::max(1, cfg_.unseen_min_cells / 2)) continue;
        p.viewpoints.push_back(Viewpoint{Vec3(pos.x(), pos.y(), z_), yaw, gain});
      }
    std::stable_sort(p.viewpoints.begin(), p.viewpoints.end(),
                     [](const Viewpoint& a, const Viewpoint& b) { return a.gain > b.gain; });
    if (p.viewpoints.size() > 3) p.viewpoints.resize(3);
    p.id = int(out.size());
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace ussnav
