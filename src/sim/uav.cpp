#include "ussnav/sim/uav.hpp"

#include <algorithm>
#include <cmath>

namespace ussnav {

Uav::Uav(const UavConfig& cfg, const Pose& start) : cfg_(cfg), pose_(start) {}

void Uav::setPath(const std::vector<Vec3>& path) {
  path_ = path;
  next_ = 0;
  while (next_ < path_.size() && (path_[next_] - pose_.position).norm() < 1e-6) ++next_;
}

std::vector<Vec3> Uav::remainingPath() const {
  std::vector<Vec3> out{pose_.position};
  for (size_t i = next_; i < path_.size(); ++i) out.push_back(path_[i]);
  return out;
}

bool Uav::idle() const {
  if (!pathDone()) return false;
  return !has_yaw_target_ || std::abs(wrapAngle(yaw_target_ - pose_.yaw)) < 1e-3;
}

bool Uav::step(const GroundTruthGrid& gt, double dt) {
  // Points the UAV already stands on are reached (a path may repeat its last point: with nothing
  // left to fly, the step below would never move on to it).
  while (next_ < path_.size() && (path_[next_] - pose_.position).norm() < 1e-9) ++next_;
  // Remaining length along the path, for braking.
  double remaining = 0.0;
  if (!pathDone()) {
    remaining = (path_[next_] - pose_.position).norm();
    for (size_t i = next_; i + 1 < path_.size(); ++i) remaining += (path_[i + 1] - path_[i]).norm();
  }
  double desired_yaw = pose_.yaw;
  if (has_yaw_target_) {
    desired_yaw = yaw_target_;
  } else if (!pathDone()) {
    const Vec3 d = path_[next_] - pose_.position;
    if (d.head<2>().norm() > 1e-3) desired_yaw = std::atan2(d.y(), d.x());
  }
  const double max_turn = deg2rad(cfg_.max_yaw_rate_deg) * dt;
  const double dyaw = std::clamp(wrapAngle(desired_yaw - pose_.yaw), -max_turn, max_turn);
  pose_.yaw = wrapAngle(pose_.yaw + dyaw);

  if (pathDone()) {
    speed_ = 0.0;
    return true;
  }
  // Accelerate up to max speed, brake to stop at the end (v^2 = 2 a d).
  const double v_brake = std::sqrt(2.0 * cfg_.max_accel * remaining);
  speed_ = std::min({speed_ + cfg_.max_accel * dt, cfg_.max_speed, v_brake});
  speed_ = std::max(speed_, std::min(remaining / dt, 0.05));  // never stall short of the goal
  double move = std::min(speed_ * dt, remaining);
  const double moved = move;
  Vec3 pos = pose_.position;
  size_t next = next_;
  std::vector<Vec3> visited{pos};  // the polyline actually swept this step (corners included)
  while (move > 1e-12 && next < path_.size()) {
    const Vec3 d = path_[next] - pos;
    const double len = d.norm();
    if (len <= move) {
      pos = path_[next++];
      move -= len;
    } else {
      pos += d / len * move;
      move = 0;
    }
    visited.push_back(pos);
  }
  // Check the swept polyline at sub-voxel spacing so a fast step cannot tunnel through a wall.
  for (size_t k = 1; k < visited.size(); ++k) {
    const Vec3 from = visited[k - 1], to = visited[k];
    const int checks = std::max(1, int(std::ceil((to - from).norm() / (0.5 * gt.resolution()))));
    for (int i = 1; i <= checks; ++i) {
      const Vec3 p = from + (to - from) * (double(i) / checks);
      if (gt.sphereCollides(p, cfg_.radius)) {
        ++collisions_;
        speed_ = 0.0;
        path_.clear();
        next_ = 0;
        return false;
      }
    }
  }
  travelled_ += moved;
  pose_.position = pos;
  next_ = next;
  return true;
}

}  // namespace ussnav
