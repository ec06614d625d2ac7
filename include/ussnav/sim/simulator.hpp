#pragma once
// The headless simulator: a World with its ground truth, the UAV's sensors and a ground-truth
// planner for evaluation. sense() renders what the UAV perceives at a pose: a LiDAR scan when
// the config maps with the LiDAR (the paper's set-up) and always a depth frame with instance
// ids (for objects, and for the map in the camera-only set-up).

#include <optional>
#include <string>
#include <unordered_map>

#include "ussnav/core/config.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/gt_paths.hpp"
#include "ussnav/sim/sensors.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

struct SensedFrame {
  Pose pose;
  double time = 0.0;
  std::optional<PointCloudScan> scan;
  DepthFrame depth;
};

class Simulator {
 public:
  Simulator(World world, const Config& cfg, uint64_t seed = 1);
  SensedFrame sense(const Pose& pose, double time);

  const World& world() const { return world_; }
  const GroundTruthGrid& groundTruth() const { return gt_; }
  const GtPlanner& planner() const { return planner_; }
  // Instance id -> category, what the oracle detector needs (and nothing else may read).
  std::unordered_map<uint32_t, std::string> instanceLabels() const;
  // The world's start pose moved to the nearest free cell at flight height.
  Pose startPose() const;

 private:
  World world_;
  Config cfg_;
  GroundTruthGrid gt_;
  GtPlanner planner_;
  DepthCamera camera_;
  Lidar lidar_;
};

}  // namespace ussnav
