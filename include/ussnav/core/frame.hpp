#pragma once
// Sensor frames as they flow from a FrameSource (simulator or dataset) into the pipeline.
// Plain data, no behaviour: mapping and perception read them, the simulator writes them.

#include <cstdint>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

// Pinhole intrinsics. Camera frame: x right, y down, z forward (optical convention).
struct Intrinsics {
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  static Intrinsics fromFov(int width, int height, double hfov_rad, double vfov_rad);
};

// A depth image with its camera pose. depth[v*width+u] is the z-depth in metres along the
// optical axis (ROS REP 117): 0 or +inf = no return (nothing within max_range, in z-depth, so
// consumers may take the pixel's ray as free up to there); -inf = too close to measure; NaN =
// invalid. Neither of the last two says anything about free space. instance (optional, same
// size) is the ground-truth object instance id per pixel, 0 = no object (walls, floor, none).
struct DepthFrame {
  Intrinsics K;
  Iso3 T_world_camera = Iso3::Identity();  // camera-to-world (optical frame)
  std::vector<float> depth;
  std::vector<uint16_t> instance;
  double max_range = 5.0;                  // z-depth; no-return pixels are free up to this
  double stamp = 0.0;                      // seconds
};

// A LiDAR scan in the world frame: hit points, plus unit directions of rays with no return
// (free up to max_range).
struct PointCloudScan {
  Vec3 origin = Vec3::Zero();
  std::vector<Vec3f> points;
  std::vector<Vec3f> no_return_dirs;
  double max_range = 40.0;
  double stamp = 0.0;
};

// Rotation from the camera optical frame (z forward, x right, y down) to the UAV body frame
// (x forward, y left, z up), with the camera pitched down by `pitch` radians.
Mat3 opticalToBody(double pitch = 0.0);

}  // namespace ussnav
