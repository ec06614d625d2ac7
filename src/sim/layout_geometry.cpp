#include "ussnav/sim/layout_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace ussnav {

std::array<Vec2, 4> footprintCorners(const OrientedBox& b) {
  const Vec2 c(b.center.x(), b.center.y());
  const Vec2 ux(std::cos(b.yaw), std::sin(b.yaw)), uy(-std::sin(b.yaw), std::cos(b.yaw));
  const Vec2 ex = ux * b.half_extents.x(), ey = uy * b.half_extents.y();
  return {c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey};
}

bool footprintsOverlap(const OrientedBox& a, const OrientedBox& b, double gap) {
  const auto ca = footprintCorners(a), cb = footprintCorners(b);
  const double axes_yaw[4] = {a.yaw, a.yaw + kPi / 2, b.yaw, b.yaw + kPi / 2};
  for (double t : axes_yaw) {
    const Vec2 n(std::cos(t), std::sin(t));
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (const auto& p : ca) amin = std::min(amin, n.dot(p)), amax = std::max(amax, n.dot(p));
    for (const auto& p : cb) bmin = std::min(bmin, n.dot(p)), bmax = std::max(bmax, n.dot(p));
    // Separated on this axis when the gap between the projections is at least `gap`
    // (with gap 0, touching counts as separated up to rounding).
    if (amax + gap <= bmin + 1e-9 || bmax + gap <= amin + 1e-9) return false;
  }
  return true;
}

bool boxesOverlap(const OrientedBox& a, const OrientedBox& b, double gap) {
  const double a0 = a.center.z() - a.half_extents.z(), a1 = a.center.z() + a.half_extents.z();
  const double b0 = b.center.z() - b.half_extents.z(), b1 = b.center.z() + b.half_extents.z();
  if (a1 <= b0 + 1e-6 || b1 <= a0 + 1e-6) return false;
  return footprintsOverlap(a, b, std::max(gap, 1e-6));
}

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

double distanceToBoundary(const Vec2& p, const std::vector<Vec2>& poly) {
  double best = 1e300;
  for (size_t i = 0; i < poly.size(); ++i)
    best = std::min(best, pointSegmentDistance(p, poly[i], poly[(i + 1) % poly.size()]));
  return best;
}

double distanceToFootprint(const Vec2& p, const OrientedBox& b) {
  const Vec2 d = p - Vec2(b.center.x(), b.center.y());
  const double c = std::cos(b.yaw), s = std::sin(b.yaw);
  const double lx = std::abs(c * d.x() + s * d.y()) - b.half_extents.x();
  const double ly = std::abs(-s * d.x() + c * d.y()) - b.half_extents.y();
  return Vec2(std::max(lx, 0.0), std::max(ly, 0.0)).norm();
}

bool footprintInsidePolygon(const OrientedBox& b, const std::vector<Vec2>& poly, double margin) {
  for (const auto& c : footprintCorners(b))
    if (!pointInPolygon(c, poly) || distanceToBoundary(c, poly) < margin) return false;
  // A reflex vertex of an L-shaped room can sit inside the footprint with all corners inside.
  for (const auto& v : poly)
    if (distanceToFootprint(v, b) < std::max(margin, 1e-9)) return false;
  return true;
}

std::vector<std::pair<double, double>> solidRuns(const Wall& w, bool (*cut)(const Opening&)) {
  const double len = (w.b - w.a).norm();
  std::vector<std::pair<double, double>> runs;
  if (len < 1e-9) return runs;
  std::vector<std::pair<double, double>> gaps;
  for (const Opening& op : w.openings)
    if (cut(op)) gaps.emplace_back(std::clamp(op.start, 0.0, len), std::clamp(op.end, 0.0, len));
  std::sort(gaps.begin(), gaps.end());
  double s = 0.0;
  for (const auto& [g0, g1] : gaps) {
    if (g0 - s >= 1e-6) runs.push_back({s, g0});
    s = std::max(s, g1);
  }
  if (len - s >= 1e-6) runs.push_back({s, len});
  return runs;
}

}  // namespace ussnav
