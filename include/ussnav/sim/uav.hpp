#pragma once
// Kinematic UAV: a point with speed, acceleration and yaw-rate limits that follows a polyline.
// It never enters occupied ground truth: a step whose sphere would touch an obstacle is a
// counted collision, the UAV stays at its last free position and drops the path.

#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/sim/ground_truth.hpp"

namespace ussnav {

class Uav {
 public:
  Uav(const UavConfig& cfg, const Pose& start);

  // Follows `path` from the current position (the first point may be the current one).
  void setPath(const std::vector<Vec3>& path);
  // Desired heading; when unset the UAV faces its direction of travel.
  void setYawTarget(double yaw) { yaw_target_ = yaw, has_yaw_target_ = true; }
  void clearYawTarget() { has_yaw_target_ = false; }
  // Advances by dt seconds. Returns false if this step collided.
  bool step(const GroundTruthGrid& gt, double dt);

  const Pose& pose() const { return pose_; }
  double speed() const { return speed_; }
  double distanceTravelled() const { return travelled_; }
  int collisions() const { return collisions_; }
  // True when the path is finished (or empty) and the yaw target is reached.
  bool idle() const;
  bool pathDone() const { return next_ >= path_.size(); }
  // The current position followed by the path points not reached yet.
  std::vector<Vec3> remainingPath() const;
  const UavConfig& config() const { return cfg_; }

 private:
  UavConfig cfg_;
  Pose pose_;
  std::vector<Vec3> path_;
  size_t next_ = 0;
  double speed_ = 0.0;
  double travelled_ = 0.0;
  int collisions_ = 0;
  double yaw_target_ = 0.0;
  bool has_yaw_target_ = false;
};

}  // namespace ussnav
