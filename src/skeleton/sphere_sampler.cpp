#include "ussnav/skeleton/sphere_sampler.hpp"

#include <cmath>

namespace ussnav {

std::vector<Vec3> fibonacciSphere(int n) {
  std::vector<Vec3> out;
  if (n <= 0) return out;
  out.reserve(size_t(n));
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    // Offsetting by half a step keeps the poles out of the set: no ray runs exactly along z,
    // where voxel walls of floors and ceilings would make hull points coplanar.
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

}  // namespace ussnav
