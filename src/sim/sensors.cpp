#include "ussnav/sim/sensors.hpp"

#include <cmath>
#include <limits>

namespace ussnav {

DepthCamera::DepthCamera(const CameraConfig& cfg, uint64_t seed)
    : cfg_(cfg),
      K_(Intrinsics::fromFov(cfg.width, cfg.height, deg2rad(cfg.hfov_deg), deg2rad(cfg.vfov_deg))),
      rng_(seed) {
  rays_.reserve(size_t(K_.width) * K_.height);
  for (int v = 0; v < K_.height; ++v)
    for (int u = 0; u < K_.width; ++u) {
      const Vec3 d = Vec3((u - K_.cx) / K_.fx, (v - K_.cy) / K_.fy, 1.0).normalized();
      rays_.push_back(d);
      zfac_.push_back(float(d.z()));
    }
}

Iso3 DepthCamera::cameraPose(const Pose& body) const {
  Iso3 t = Iso3::Identity();
  t.translation() = body.position;
  t.linear() = Eigen::AngleAxisd(body.yaw, Vec3::UnitZ()).toRotationMatrix() *
               opticalToBody(deg2rad(cfg_.pitch_deg));
  return t;
}

DepthFrame DepthCamera::render(const GroundTruthGrid& gt, const Pose& body, double stamp) {
  DepthFrame f;
  f.K = K_;
  f.T_world_camera = cameraPose(body);
  f.max_range = cfg_.max_range;
  f.stamp = stamp;
  const size_t n = rays_.size();
  f.depth.assign(n, 0.0f);
  f.instance.assign(n, 0);
  const Mat3 R = f.T_world_camera.linear();
  const Vec3 o = body.position;
  const bool noisy = cfg_.noise_std > 0.0 || cfg_.dropout > 0.0;
  const float too_close = -std::numeric_limits<float>::infinity();  // REP 117: too close to measure
  const float invalid = std::numeric_limits<float>::quiet_NaN();
  for (size_t i = 0; i < n; ++i) {
    // max_range bounds the z-depth, as DepthFrame::max_range does for the consumers, which
    // carve a no-return pixel free up to that z-depth: a ray off the optical axis is cast to
    // the longer range max_range / zfac, or a wall beyond max_range in range but not in z-depth
    // would be reported as no return and carved through.
    const GroundTruthGrid::Hit h = gt.raycast(o, R * rays_[i], cfg_.max_range / zfac_[i]);
    if (!h.hit) continue;
    double z = h.range * zfac_[i];
    if (h.range < cfg_.min_range) {  // too close: the D455 returns nothing, and nothing is carved
      f.depth[i] = too_close;
      continue;
    }
    f.instance[i] = uint16_t(gt.instanceOfLabel(h.label));
    if (noisy) {
      if (cfg_.dropout > 0.0 && rng_.bernoulli(cfg_.dropout)) {  // a lost pixel: invalid, not "no return"
        f.instance[i] = 0;
        f.depth[i] = invalid;
        continue;
      }
      if (cfg_.noise_std > 0.0) z = std::max(0.01, z + rng_.normal(0.0, cfg_.noise_std));
    }
    f.depth[i] = float(std::min(z, cfg_.max_range));
  }
  return f;
}

Lidar::Lidar(const LidarConfig& cfg, uint64_t seed) : cfg_(cfg), rng_(seed) {
  // Golden-angle spiral over the elevation band, uniform in sin(elevation) so the density
  // per solid angle is even, as the Mid-360's rosette roughly is.
  const double s0 = std::sin(deg2rad(cfg.vmin_deg)), s1 = std::sin(deg2rad(cfg.vmax_deg));
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  dirs_.reserve(size_t(cfg.points_per_scan));
  for (int i = 0; i < cfg.points_per_scan; ++i) {
    const double sz = s0 + (s1 - s0) * (i + 0.5) / cfg.points_per_scan;
    const double r = std::sqrt(std::max(0.0, 1.0 - sz * sz));
    const double az = i * golden;
    dirs_.emplace_back(r * std::cos(az), r * std::sin(az), sz);
  }
}

PointCloudScan Lidar::scan(const GroundTruthGrid& gt, const Pose& body, double stamp) {
  PointCloudScan s;
  s.origin = body.position;
  s.max_range = cfg_.max_range;
  s.stamp = stamp;
  s.points.reserve(dirs_.size());
  // Non-repetitive: rotate the whole pattern by an irrational fraction each scan.
  const double spin = body.yaw + double(scans_++) * 0.7639320225;
  const Mat3 R = Eigen::AngleAxisd(spin, Vec3::UnitZ()).toRotationMatrix();
  for (const Vec3& d0 : dirs_) {
    const Vec3 d = R * d0;
    const GroundTruthGrid::Hit h = gt.raycast(s.origin, d, cfg_.max_range);
    if (!h.hit) {
      s.no_return_dirs.push_back(d.cast<float>());
      continue;
    }
    if (h.range < cfg_.min_range) continue;
    double r = h.range;
    if (cfg_.noise_std > 0.0) r = std::max(cfg_.min_range, r + rng_.normal(0.0, cfg_.noise_std));
    s.points.push_back((s.origin + d * r).cast<float>());
  }
  return s;
}

}  // namespace ussnav
