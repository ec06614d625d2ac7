#include "ussnav/core/frame.hpp"

#include <cmath>

namespace ussnav {

Intrinsics Intrinsics::fromFov(int width, int height, double hfov, double vfov) {
  Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = 0.5 * width / std::tan(0.5 * hfov);
  k.fy = 0.5 * height / std::tan(0.5 * vfov);
  k.cx = 0.5 * width - 0.5;
  k.cy = 0.5 * height - 0.5;
  return k;
}

Mat3 opticalToBody(double pitch) {
  Mat3 r;
  // columns: optical x (right) -> body -y; optical y (down) -> body -z; optical z -> body x
  r << 0, 0, 1,
      -1, 0, 0,
      0, -1, 0;
  const Mat3 tilt = Eigen::AngleAxisd(pitch, Vec3::UnitY()).toRotationMatrix();
  return tilt * r;
}

}  // namespace ussnav
