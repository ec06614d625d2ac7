#include "ussnav/sim/world.hpp"

#include <cmath>

namespace ussnav {

namespace {
Vec3 toLocal(const OrientedBox& b, const Vec3& p) {
  const Vec3 d = p - b.center;
  const double c = std::cos(b.yaw), s = std::sin(b.yaw);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
}
}  // namespace

bool OrientedBox::contains(const Vec3& p, double margin) const {
  const Vec3 l = toLocal(*this, p);
  return (l.cwiseAbs().array() <= (half_extents.array() + margin)).all();
}

double OrientedBox::distance(const Vec3& p) const {
  const Vec3 l = toLocal(*this, p);
  return (l.cwiseAbs() - half_extents).cwiseMax(0.0).norm();
}

Aabb OrientedBox::bounds() const {
  const double c = std::abs(std::cos(yaw)), s = std::abs(std::sin(yaw));
  const Vec3 e(c * half_extents.x() + s * half_extents.y(), s * half_extents.x() + c * half_extents.y(),
               half_extents.z());
  Aabb a;
  a.extend(center - e);
  a.extend(center + e);
  return a;
}

const Room* World::room(int id) const {
  for (const auto& r : rooms)
    if (r.id == id) return &r;
  return nullptr;
}

const Object* World::object(int id) const {
  for (const auto& o : objects)
    if (o.id == id) return &o;
  return nullptr;
}

const Room* World::roomAt(const Vec2& p) const {
  for (const auto& r : rooms)
    if (pointInPolygon(p, r.polygon)) return &r;
  return nullptr;
}

Aabb World::bounds() const {
  Aabb b;
  for (const auto& r : rooms)
    for (const auto& p : r.polygon) {
      b.extend(Vec3(p.x(), p.y(), r.floor_z));
      b.extend(Vec3(p.x(), p.y(), r.ceiling_z));
    }
  for (const auto& w : walls) {
    b.extend(Vec3(w.a.x(), w.a.y(), w.z0));
    b.extend(Vec3(w.b.x(), w.b.y(), w.z1));
  }
  for (const auto& o : objects) b.extend(o.box.bounds());
  for (const auto& c : obstacles.cells) {
    const Vec3 lo = obstacles.origin + c.cast<double>() * obstacles.resolution;
    b.extend(lo);
    b.extend(lo + Vec3::Constant(obstacles.resolution));
  }
  return b;
}

double polygonArea(const std::vector<Vec2>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& poly) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

Vec2 polygonCentroid(const std::vector<Vec2>& poly) {
  const double a = polygonArea(poly);
  if (std::abs(a) < 1e-12) {
    Vec2 s = Vec2::Zero();
    for (const auto& p : poly) s += p;
    return poly.empty() ? s : Vec2(s / double(poly.size()));
  }
  Vec2 c = Vec2::Zero();
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    const double cr = p.x() * q.y() - q.x() * p.y();
    c += (p + q) * cr;
  }
  return c / (6.0 * a);
}

}  // namespace ussnav
