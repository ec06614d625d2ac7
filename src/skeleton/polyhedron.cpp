#include "ussnav/skeleton/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

namespace ussnav {

namespace {

// Qhull reports degenerate input (the normal case for a seed against a flat wall with all rays
// blocked) on its error stream; we turn that into an empty hull, so its text goes nowhere.
FILE* qhullErrorSink() {
  static FILE* sink = std::fopen("/dev/null", "w");
  return sink ? sink : stderr;
}

}  // namespace

ConvexHull convexHull(const std::vector<Vec3>& points) {
  ConvexHull hull;
  if (points.size() < 4) return hull;
  std::vector<coordT> coords;
  coords.reserve(points.size() * 3);
  for (const Vec3& p : points) {
    if (!p.allFinite()) return hull;
    coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  }
  qhT qh_storage;
  qhT* qh = &qh_storage;
  FILE* err = qhullErrorSink();
  qh_zero(qh, err);
  // Qt: triangulated output, so every face is a triangle; merged coplanar facets (points on one
  // voxel wall) become several triangles sharing one plane.
  char options[] = "qhull Qt";
  const int exitcode = qh_new_qhull(qh, 3, int(points.size()), coords.data(), False, options,
                                    nullptr, err);
  if (exitcode == 0) {
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      std::array<int, 3> tri{-1, -1, -1};
      int n = 0;
      FOREACHvertex_(facet->vertices) {
        if (n < 3) tri[size_t(n)] = qh_pointid(qh, vertex->point);
        ++n;
      }
      if (n != 3 || tri[0] < 0 || tri[1] < 0 || tri[2] < 0) continue;
      const Vec3 normal(facet->normal[0], facet->normal[1], facet->normal[2]);
      const Vec3& a = points[size_t(tri[0])];
      const Vec3& b = points[size_t(tri[1])];
      const Vec3& c = points[size_t(tri[2])];
      // Qhull's vertex order depends on facet orientation flags; order by the outward normal.
      if ((b - a).cross(c - a).dot(normal) < 0) std::swap(tri[1], tri[2]);
      hull.faces.push_back(tri);
      hull.normals.push_back(normal);
      hull.offsets.push_back(facet->offset);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (exitcode != 0) hull = ConvexHull{};
  return hull;
}

bool Polyhedron::contains(const Vec3& p, double tolerance) const {
  if (faces.empty()) return false;
  if ((p.array() < bounds.min.array() - tolerance).any() ||
      (p.array() > bounds.max.array() + tolerance).any())
    return false;
  for (size_t f = 0; f < faces.size(); ++f)
    if (normals[f].dot(p) + offsets[f] > tolerance) return false;
  return true;
}

Vec3 Polyhedron::faceCentroid(int f) const {
  const auto& t = faces[size_t(f)];
  return (points[size_t(t[0])] + points[size_t(t[1])] + points[size_t(t[2])]) / 3.0;
}

double Polyhedron::faceArea(int f) const {
  const auto& t = faces[size_t(f)];
  const Vec3& a = points[size_t(t[0])];
  return 0.5 * (points[size_t(t[1])] - a).cross(points[size_t(t[2])] - a).norm();
}

std::vector<int> Polyhedron::hullVertices() const {
  std::vector<char> used(points.size(), 0);
  for (const auto& t : faces)
    for (int i : t) used[size_t(i)] = 1;
  std::vector<int> out;
  for (size_t i = 0; i < used.size(); ++i)
    if (used[i]) out.push_back(int(i));
  return out;
}

namespace {

// Volume, centroid, radius and bounds from the faces (normals/offsets must be set).
void finishGeometry(Polyhedron& p) {
  p.volume = 0.0;
  p.centroid = Vec3::Zero();
  p.radius = 0.0;
  p.bounds = Aabb{};
  if (p.faces.empty()) return;
  const std::vector<int> verts = p.hullVertices();
  Vec3 ref = Vec3::Zero();
  for (int v : verts) {
    ref += p.points[size_t(v)];
    p.bounds.extend(p.points[size_t(v)]);
  }
  ref /= double(verts.size());
  // Sum of tetrahedra (ref, face): signed volumes, so the result is right even if ref lay
  // outside (it cannot for a convex hull, but a hand-made face list may be odd).
  Vec3 weighted = Vec3::Zero();
  for (const auto& t : p.faces) {
    const Vec3& a = p.points[size_t(t[0])];
    const Vec3& b = p.points[size_t(t[1])];
    const Vec3& c = p.points[size_t(t[2])];
    const double v = (a - ref).dot((b - ref).cross(c - ref)) / 6.0;
    p.volume += v;
    weighted += v * (ref + a + b + c) / 4.0;
  }
  if (p.volume <= 1e-12) {
    p.volume = 0.0;
    p.centroid = ref;
  } else {
    p.centroid = weighted / p.volume;
  }
  for (int v : verts) p.radius = std::max(p.radius, (p.points[size_t(v)] - p.centroid).norm());
}

}  // namespace

Polyhedron buildPolyhedron(std::vector<Vec3> points, std::vector<VertexKind> kinds) {
  Polyhedron p;
  ConvexHull hull = convexHull(points);
  p.points = std::move(points);
  p.kinds = std::move(kinds);
  p.kinds.resize(p.points.size(), VertexKind::Free);
  p.faces = std::move(hull.faces);
  p.normals = std::move(hull.normals);
  p.offsets = std::move(hull.offsets);
  finishGeometry(p);
  return p;
}

Polyhedron makePolyhedron(std::vector<Vec3> points, std::vector<VertexKind> kinds,
                          std::vector<std::array<int, 3>> faces) {
  Polyhedron p;
  p.points = std::move(points);
  p.kinds = std::move(kinds);
  p.kinds.resize(p.points.size(), VertexKind::Free);
  p.faces = std::move(faces);
  for (const auto& t : p.faces) {
    const Vec3& a = p.points[size_t(t[0])];
    Vec3 n = (p.points[size_t(t[1])] - a).cross(p.points[size_t(t[2])] - a);
    const double len = n.norm();
    n = len > 0 ? Vec3(n / len) : Vec3::UnitZ();
    p.normals.push_back(n);
    p.offsets.push_back(-n.dot(a));
  }
  finishGeometry(p);
  return p;
}

double cubePenetration(const Polyhedron& p, const Vec3& c, double h) {
  if (!p.valid()) return -std::numeric_limits<double>::infinity();
  double pen = std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const Vec3& n = p.normals[f];
    pen = std::min(pen, h * n.cwiseAbs().sum() - (n.dot(c) + p.offsets[f]));
    if (pen <= 0) return pen;
  }
  return pen;
}

Polyhedron clipPolyhedron(const Polyhedron& p, const Vec3& normal, double d) {
  if (!p.valid()) return p;
  std::vector<Vec3> pts;
  std::vector<VertexKind> kinds;
  for (int v : p.hullVertices())
    if (normal.dot(p.points[size_t(v)]) <= d) {
      pts.push_back(p.points[size_t(v)]);
      kinds.push_back(p.kinds[size_t(v)]);
    }
  // Every hull edge appears in two triangles; take it once, from the lower index.
  for (const auto& t : p.faces)
    for (int i = 0; i < 3; ++i) {
      const int a = t[size_t(i)], b = t[size_t((i + 1) % 3)];
      if (a > b) continue;
      const double da = normal.dot(p.points[size_t(a)]) - d, db = normal.dot(p.points[size_t(b)]) - d;
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
        pts.push_back(p.points[size_t(a)] + (da / (da - db)) * (p.points[size_t(b)] - p.points[size_t(a)]));
        kinds.push_back(VertexKind::Obstacle);
      }
    }
  return buildPolyhedron(std::move(pts), std::move(kinds));
}

std::optional<Polyhedron> cutOutCube(const Polyhedron& p, const Vec3& c, double h, const Vec3& keep) {
  // Candidate planes n . x <= d, each touching the cube on the side of `keep`.
  std::vector<std::pair<Vec3, double>> planes;
  const Vec3 dir = c - keep;
  if (dir.norm() > 1e-9) {
    const Vec3 n = dir.normalized();
    planes.emplace_back(n, n.dot(c) - h * n.cwiseAbs().sum());
  }
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12) continue;
    Vec3 n = Vec3::Zero();
    n[a] = dir[a] > 0 ? 1.0 : -1.0;
    planes.emplace_back(n, n.dot(c) - h);
  }
  const std::vector<int> verts = p.hullVertices();
  double best_depth = std::numeric_limits<double>::infinity();
  int best = -1;
  for (size_t i = 0; i < planes.size(); ++i) {
    const auto& [n, d] = planes[i];
    if (n.dot(keep) >= d - 1e-9) continue;  // would cut `keep` away
    double depth = 0.0;
    for (int v : verts) depth = std::max(depth, n.dot(p.points[size_t(v)]) - d);
    if (depth < best_depth) {
      best_depth = depth;
      best = int(i);
    }
  }
  if (best < 0) return std::nullopt;
  return clipPolyhedron(p, planes[size_t(best)].first, planes[size_t(best)].second);
}

bool polyhedraIntersect(const Polyhedron& a, const Polyhedron& b, double tolerance) {
  if (!a.valid() || !b.valid()) return false;
  if ((a.bounds.max.array() < b.bounds.min.array() - tolerance).any() ||
      (b.bounds.max.array() < a.bounds.min.array() - tolerance).any())
    return false;
  const std::vector<int> va = a.hullVertices(), vb = b.hullVertices();
  // A face plane of one with every vertex of the other strictly outside separates them.
  auto separatedBy = [tolerance](const Polyhedron& p, const Polyhedron& q, const std::vector<int>& qv) {
    for (size_t f = 0; f < p.faces.size(); ++f) {
      bool all_outside = true;
      for (int v : qv)
        if (p.normals[f].dot(q.points[size_t(v)]) + p.offsets[f] <= tolerance) {
          all_outside = false;
          break;
        }
      if (all_outside) return true;
    }
    return false;
  };
  return !separatedBy(a, b, vb) && !separatedBy(b, a, va);
}

}  // namespace ussnav
