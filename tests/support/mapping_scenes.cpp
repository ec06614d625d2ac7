#include "support/mapping_scenes.hpp"

#include <cmath>
#include <limits>

#include "ussnav/core/random.hpp"

namespace ussnav::test {

namespace {

// Slab test: entry distance of the ray into box b (0 if o is inside), +inf if it misses.
double rayBox(const Aabb& b, const Vec3& o, const Vec3& dir) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dir[i]) < 1e-15) {
      if (o[i] < b.min[i] || o[i] > b.max[i]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double a = (b.min[i] - o[i]) / dir[i], c = (b.max[i] - o[i]) / dir[i];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Aabb b;
  b.min = Vec3(x0, y0, z0);
  b.max = Vec3(x1, y1, z1);
  return b;
}

}  // namespace

double BoxScene::raycast(const Vec3& o, const Vec3& dir, double max_dist) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Aabb& b : solids) best = std::min(best, rayBox(b, o, dir));
  return best <= max_dist ? best : std::numeric_limits<double>::infinity();
}

bool BoxScene::insideSolid(const Vec3& p) const {
  for (const Aabb& b : solids)
    if (b.contains(p)) return true;
  return false;
}

bool BoxScene::voxelFreeInTruth(const Vec3i& key, double res) const {
  const Vec3 lo = key.cast<double>() * res, hi = lo + Vec3::Constant(res);
  for (const Aabb& b : solids)
    if ((lo.array() < b.max.array()).all() && (hi.array() > b.min.array()).all()) return false;
  return true;
}

bool BoxScene::voxelNearSurface(const Vec3i& key, double res, double margin) const {
  const Vec3 lo = key.cast<double>() * res - Vec3::Constant(margin);
  const Vec3 hi = lo + Vec3::Constant(res + 2 * margin);
  bool meets = false;
  for (const Aabb& b : solids)
    meets |= (lo.array() <= b.max.array()).all() && (hi.array() >= b.min.array()).all();
  if (!meets) return false;
  // Look for free space inside the grown box on a 6 x 6 x 6 lattice (corners included).
  constexpr int n = 6;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 f(double(i) / (n - 1), double(j) / (n - 1), double(k) / (n - 1));
        if (!insideSolid(lo + f.cwiseProduct(hi - lo))) return true;
      }
  return false;
}

BoxScene boxRoom(const Vec3& lo, const Vec3& hi, double w, bool furnished) {
  BoxScene s;
  s.solids.push_back(box(lo.x() - w, lo.y() - w, lo.z() - w, hi.x() + w, hi.y() + w, lo.z()));  // floor
  s.solids.push_back(box(lo.x() - w, lo.y() - w, hi.z(), hi.x() + w, hi.y() + w, hi.z() + w));  // ceiling
  s.solids.push_back(box(lo.x() - w, lo.y() - w, lo.z(), lo.x(), hi.y() + w, hi.z()));         // west
  s.solids.push_back(box(hi.x(), lo.y() - w, lo.z(), hi.x() + w, hi.y() + w, hi.z()));         // east
  s.solids.push_back(box(lo.x(), lo.y() - w, lo.z(), hi.x(), lo.y(), hi.z()));                 // south
  s.solids.push_back(box(lo.x(), hi.y(), lo.z(), hi.x(), hi.y() + w, hi.z()));                 // north
  if (furnished) {
    const Vec3 c = 0.5 * (lo + hi), e = hi - lo;
    s.solids.push_back(box(c.x() + 0.17 * e.x(), c.y() - 0.23 * e.y(), lo.z(), c.x() + 0.33 * e.x(),
                           c.y() - 0.07 * e.y(), lo.z() + 0.74));                            // table
    s.solids.push_back(box(lo.x(), hi.y() - 0.47, lo.z(), lo.x() + 1.13, hi.y(), lo.z() + 1.87));  // cabinet
    s.solids.push_back(box(c.x() - 0.83, c.y() + 0.61, lo.z(), c.x() - 0.51, c.y() + 0.93, hi.z()));  // pillar
  }
  return s;
}

BoxScene corridor(double length, double width, double height) {
  BoxScene s;
  const double w = 0.2, hw = 0.5 * width;
  s.solids.push_back(box(-w - 1, -hw - w, -w, length + w + 1, hw + w, 0.0));
  s.solids.push_back(box(-w - 1, -hw - w, height, length + w + 1, hw + w, height + w));
  s.solids.push_back(box(-w - 1, -hw - w, 0, length + w + 1, -hw, height));
  s.solids.push_back(box(-w - 1, hw, 0, length + w + 1, hw + w, height));
  s.solids.push_back(box(-w - 1, -hw, 0, -1, hw, height));
  s.solids.push_back(box(length + 1, -hw, 0, length + w + 1, hw, height));
  for (int i = 0; 10.0 * i + 5 < length; ++i) {
    const double x = 10.0 * i + 5, side = i % 2 ? 1 : -1;
    s.solids.push_back(box(x, side > 0 ? hw - 0.45 : -hw, 0, x + 0.6, side > 0 ? hw : -hw + 0.45, 0.9));
  }
  return s;
}

Iso3 cameraPose(const Vec3& position, double yaw, double pitch) {
  Iso3 t = Iso3::Identity();
  t.translation() = position;
  t.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix() * opticalToBody(pitch);
  return t;
}

DepthFrame renderDepth(const BoxScene& scene, const Intrinsics& K, const Iso3& T, double max_range,
                       double noise_std, uint64_t seed) {
  DepthFrame f;
  f.K = K;
  f.T_world_camera = T;
  f.max_range = max_range;
  f.depth.assign(size_t(K.width) * size_t(K.height), 0.f);
  Rng rng(seed);
  const Vec3 o = T.translation();
  for (int v = 0; v < K.height; ++v)
    for (int u = 0; u < K.width; ++u) {
      const Vec3 ray_cam((u - K.cx) / K.fx, (v - K.cy) / K.fy, 1.0);  // unit z-depth
      const double len = ray_cam.norm();
      const double t = scene.raycast(o, T.linear() * ray_cam / len, max_range * len);
      if (!std::isfinite(t)) continue;
      double z = t / len;
      if (noise_std > 0) z += rng.normal(0.0, noise_std);
      if (z > max_range || z <= 0) continue;
      f.depth[size_t(v) * size_t(K.width) + size_t(u)] = float(z);
    }
  return f;
}

PointCloudScan renderScan(const BoxScene& scene, const Vec3& origin, int n, double vmin_deg,
                          double vmax_deg, double max_range, double phase, double noise_std,
                          uint64_t seed) {
  PointCloudScan scan;
  scan.origin = origin;
  scan.max_range = max_range;
  Rng rng(seed);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  const double s0 = std::sin(deg2rad(vmin_deg)), s1 = std::sin(deg2rad(vmax_deg));
  for (int i = 0; i < n; ++i) {
    const double az = phase + golden * i;
    const double el = std::asin(s0 + (s1 - s0) * (i + 0.5) / n);  // uniform over the sphere band
    const Vec3 dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const double t = scene.raycast(origin, dir, max_range);
    if (!std::isfinite(t)) {
      scan.no_return_dirs.push_back(dir.cast<float>());
      continue;
    }
    const double r = noise_std > 0 ? t + rng.normal(0.0, noise_std) : t;
    scan.points.push_back((origin + dir * r).cast<float>());
  }
  return scan;
}

}  // namespace ussnav::test
