#pragma once
// Simulated sensors by ray casting the ground truth: a depth camera like the RealSense D455
// (z-depth + per-pixel instance id) and a LiDAR like the Livox Mid-360 (360 deg x -7..52 deg,
// non-repetitive pattern). Ray directions are precomputed per configuration; each render is
// one DDA per pixel/point. Noise and dropout come from a seeded Rng (deterministic).
// Depth pixels follow frame.hpp (REP 117): camera.max_range bounds the z-depth (each pixel's
// ray is cast to max_range / cos of its angle off the axis), a surface nearer than min_range is
// -inf (too close), a dropped pixel NaN (invalid), and 0 only means nothing within max_range,
// so a consumer carving no-return pixels free never carves through a surface.

#include <cstdint>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/frame.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/sim/ground_truth.hpp"

namespace ussnav {

class DepthCamera {
 public:
  DepthCamera(const CameraConfig& cfg, uint64_t seed = 1);
  // Renders at a UAV body pose (camera at the body origin looking along body +x).
  DepthFrame render(const GroundTruthGrid& gt, const Pose& body, double stamp = 0.0);
  const Intrinsics& intrinsics() const { return K_; }
  // Camera-to-world transform (optical frame) at a body pose.
  Iso3 cameraPose(const Pose& body) const;

 private:
  CameraConfig cfg_;
  Intrinsics K_;
  std::vector<Vec3> rays_;    // unit directions in the optical frame
  std::vector<float> zfac_;   // z component of each unit ray (range -> z-depth)
  Rng rng_;
};

class Lidar {
 public:
  Lidar(const LidarConfig& cfg, uint64_t seed = 1);
  // Scans from `origin` (sensor level, yaw of the body rotates the pattern).
  PointCloudScan scan(const GroundTruthGrid& gt, const Pose& body, double stamp = 0.0);

 private:
  LidarConfig cfg_;
  std::vector<Vec3> dirs_;  // body-frame unit directions
  Rng rng_;
  uint64_t scans_ = 0;
};

}  // namespace ussnav
