#include <gtest/gtest.h>

#include <cmath>

#include "ussnav/skeleton/polyhedron.hpp"
#include "ussnav/skeleton/sphere_sampler.hpp"

using namespace ussnav;

namespace {
std::vector<Vec3> cubePoints(const Vec3& lo, double side) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i)
    pts.push_back(lo + side * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return pts;
}
}  // namespace

TEST(ConvexHull, CubeGivesTwelveOutwardTriangles) {
  std::vector<Vec3> pts = cubePoints(Vec3(1, 2, 3), 2.0);
  pts.push_back(Vec3(2, 3, 4));  // interior point: not a hull vertex
  const ConvexHull hull = convexHull(pts);
  ASSERT_EQ(hull.faces.size(), 12u);
  const Vec3 c(2, 3, 4);
  for (size_t f = 0; f < hull.faces.size(); ++f) {
    const auto& t = hull.faces[f];
    for (int v : t) EXPECT_NE(v, 8) << "interior point used as a vertex";
    const Vec3 n = (pts[size_t(t[1])] - pts[size_t(t[0])]).cross(pts[size_t(t[2])] - pts[size_t(t[0])]);
    EXPECT_GT(n.dot(hull.normals[f]), 0.0) << "face " << f << " not counter-clockwise from outside";
    EXPECT_NEAR(hull.normals[f].norm(), 1.0, 1e-9);
    EXPECT_LT(hull.normals[f].dot(c) + hull.offsets[f], -0.99);  // centre is 1 m inside every face
    // The normal is axis-aligned and points away from the centre.
    EXPECT_NEAR(hull.normals[f].cwiseAbs().maxCoeff(), 1.0, 1e-9);
  }
}

TEST(Polyhedron, CubeVolumeCentroidAndContains) {
  const Polyhedron p = buildPolyhedron(cubePoints(Vec3(1, 2, 3), 2.0), {});
  ASSERT_TRUE(p.valid());
  EXPECT_EQ(p.faces.size(), 12u);
  EXPECT_NEAR(p.volume, 8.0, 1e-9);
  EXPECT_TRUE(p.centroid.isApprox(Vec3(2, 3, 4), 1e-9));
  EXPECT_NEAR(p.radius, std::sqrt(3.0), 1e-9);
  EXPECT_TRUE(p.contains(Vec3(2, 3, 4)));
  EXPECT_TRUE(p.contains(Vec3(1, 2, 3)));          // a vertex
  EXPECT_TRUE(p.contains(Vec3(2.9, 3.9, 4.9)));
  EXPECT_FALSE(p.contains(Vec3(3.01, 3, 4)));
  EXPECT_FALSE(p.contains(Vec3(0.5, 3, 4)));
  EXPECT_EQ(p.hullVertices().size(), 8u);
}

TEST(ConvexHull, DegenerateInputGivesEmptyHull) {
  // Coplanar points (a seed on a flat wall), collinear points, too few points, NaN.
  std::vector<Vec3> plane;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) plane.emplace_back(i * 0.1, j * 0.1, 1.0);
  EXPECT_TRUE(convexHull(plane).empty());
  std::vector<Vec3> line;
  for (int i = 0; i < 6; ++i) line.emplace_back(i, 2.0 * i, 0);
  EXPECT_TRUE(convexHull(line).empty());
  EXPECT_TRUE(convexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).empty());
  std::vector<Vec3> nan = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, std::nan(""))};
  EXPECT_TRUE(convexHull(nan).empty());
  EXPECT_FALSE(buildPolyhedron(plane, {}).valid());
  // Qhull state is freed between calls: a good hull after bad ones still works.
  EXPECT_EQ(convexHull(cubePoints(Vec3::Zero(), 1.0)).faces.size(), 12u);
}

TEST(ConvexHull, SpherePointsAllOnHull) {
  const std::vector<Vec3> dirs = fibonacciSphere(50);
  const Polyhedron p = buildPolyhedron(dirs, {});
  ASSERT_TRUE(p.valid());
  EXPECT_EQ(p.hullVertices().size(), 50u);
  EXPECT_EQ(p.faces.size(), 2u * 50 - 4);  // Euler: a triangulated sphere with V vertices
  // Inscribed in the unit ball, and close to its volume 4/3 pi.
  EXPECT_LT(p.volume, 4.0 / 3.0 * kPi);
  EXPECT_GT(p.volume, 0.85 * 4.0 / 3.0 * kPi);
  EXPECT_LT(p.centroid.norm(), 0.05);
}

TEST(Polyhedron, HandMadeFacesMatchQhull) {
  // A tetrahedron given by hand (CCW from outside).
  const std::vector<Vec3> pts = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Polyhedron hand = makePolyhedron(pts, {}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const Polyhedron qh = buildPolyhedron(pts, {});
  EXPECT_NEAR(hand.volume, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(qh.volume, 1.0 / 6.0, 1e-12);
  EXPECT_TRUE(hand.centroid.isApprox(Vec3::Constant(0.25), 1e-12));
  EXPECT_TRUE(qh.centroid.isApprox(Vec3::Constant(0.25), 1e-12));
  EXPECT_TRUE(hand.contains(Vec3(0.1, 0.1, 0.1)));
  EXPECT_FALSE(hand.contains(Vec3(0.5, 0.5, 0.5)));
}

TEST(Polyhedron, IntersectionOfCubes) {
  const Polyhedron a = buildPolyhedron(cubePoints(Vec3(0, 0, 0), 1.0), {});
  const Polyhedron overlapping = buildPolyhedron(cubePoints(Vec3(0.5, 0.5, 0.5), 1.0), {});
  const Polyhedron touching = buildPolyhedron(cubePoints(Vec3(1.0, 0, 0), 1.0), {});
  const Polyhedron apart = buildPolyhedron(cubePoints(Vec3(1.2, 0, 0), 1.0), {});
  const Polyhedron diagonal_apart = buildPolyhedron(cubePoints(Vec3(1.1, 1.1, 1.1), 1.0), {});
  EXPECT_TRUE(polyhedraIntersect(a, overlapping));
  EXPECT_TRUE(polyhedraIntersect(overlapping, a));
  EXPECT_TRUE(polyhedraIntersect(a, touching));
  EXPECT_FALSE(polyhedraIntersect(a, apart));
  EXPECT_FALSE(polyhedraIntersect(a, diagonal_apart));
  // A small tetrahedron fully inside the cube.
  const Polyhedron inner = buildPolyhedron({Vec3(0.2, 0.2, 0.2), Vec3(0.4, 0.2, 0.2), Vec3(0.2, 0.4, 0.2),
                                            Vec3(0.2, 0.2, 0.4)}, {});
  EXPECT_TRUE(polyhedraIntersect(a, inner));
  EXPECT_TRUE(polyhedraIntersect(inner, a));
}

TEST(FibonacciSphere, UnitAndSpread) {
  for (int n : {8, 50, 200}) {
    const std::vector<Vec3> d = fibonacciSphere(n);
    ASSERT_EQ(int(d.size()), n);
    Vec3 mean = Vec3::Zero();
    double min_sep = 10.0;
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(d[size_t(i)].norm(), 1.0, 1e-12);
      mean += d[size_t(i)];
      for (int j = 0; j < i; ++j) min_sep = std::min(min_sep, (d[size_t(i)] - d[size_t(j)]).norm());
    }
    // Balanced (mean near the centre) and no two points close: the nearest-neighbour distance of
    // a uniform spread is about sqrt(4 pi / n); demand at least half of it.
    EXPECT_LT((mean / n).norm(), 0.05) << n;
    EXPECT_GT(min_sep, 0.5 * std::sqrt(4 * kPi / n)) << n;
  }
  // Every direction of space has a sample within the spacing.
  const std::vector<Vec3> d = fibonacciSphere(50);
  for (const Vec3& probe : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 1, 1).normalized()}) {
    double best = -1;
    for (const Vec3& v : d) best = std::max(best, v.dot(probe));
    EXPECT_GT(best, std::cos(0.45)) << probe.transpose();
  }
  EXPECT_TRUE(fibonacciSphere(0).empty());
}

TEST(Polyhedron, ClipKeepsTheHalfBelowThePlane) {
  const Polyhedron cube = buildPolyhedron(cubePoints(Vec3(0, 0, 0), 2.0), {});
  // A diagonal plane x + y <= 2 (through the middle): half the volume, a triangular prism.
  const Vec3 n = Vec3(1, 1, 0).normalized();
  const Polyhedron half = clipPolyhedron(cube, n, n.dot(Vec3(1, 1, 0)));
  ASSERT_TRUE(half.valid());
  EXPECT_NEAR(half.volume, 4.0, 1e-9);
  for (int v : half.hullVertices()) EXPECT_LE(n.dot(half.points[size_t(v)]), n.dot(Vec3(1, 1, 0)) + 1e-9);
  EXPECT_TRUE(half.contains(Vec3(0.5, 0.5, 1)));
  EXPECT_FALSE(half.contains(Vec3(1.5, 1.5, 1)));
  // The new vertices lie against what was cut away.
  int cut = 0;
  for (int v : half.hullVertices()) cut += half.kinds[size_t(v)] == VertexKind::Obstacle;
  EXPECT_EQ(cut, 0);  // the plane runs through cube vertices: no edge is crossed strictly
  const Polyhedron slab = clipPolyhedron(cube, Vec3::UnitX(), 0.5);
  EXPECT_NEAR(slab.volume, 4 * 0.5, 1e-9);
  cut = 0;
  for (int v : slab.hullVertices()) cut += slab.kinds[size_t(v)] == VertexKind::Obstacle;
  EXPECT_EQ(cut, 4);
  // Nothing left: invalid.
  EXPECT_FALSE(clipPolyhedron(cube, Vec3::UnitX(), -0.1).valid());
}

TEST(Polyhedron, CubePenetrationAndShallowestCut) {
  const Polyhedron box = buildPolyhedron(cubePoints(Vec3(0, 0, 0), 2.0), {});
  const double h = 0.05;
  EXPECT_NEAR(cubePenetration(box, Vec3(1, 1, 1), h), 1.0 + h, 1e-9);
  EXPECT_NEAR(cubePenetration(box, Vec3(0.02, 1, 1), h), 0.07, 1e-9);
  EXPECT_LT(cubePenetration(box, Vec3(-0.2, 1, 1), h), 0.0);
  // A voxel near the +x face, off to the side of the keep point: the x face of the voxel is the
  // shallowest cut (a thin slab), not the plane facing `keep` (a slice through the middle).
  const Vec3 keep(0.5, 0.5, 1.0), voxel(1.9, 1.5, 1.0);
  const std::optional<Polyhedron> cut = cutOutCube(box, voxel, h, keep);
  ASSERT_TRUE(cut && cut->valid());
  EXPECT_NEAR(cut->volume, 2 * 2 * (1.9 - h), 1e-9);
  EXPECT_LE(cubePenetration(*cut, voxel, h), 1e-9);
  EXPECT_TRUE(cut->contains(keep));
  // No plane can keep a point inside the voxel itself.
  EXPECT_FALSE(cutOutCube(box, voxel, h, voxel).has_value());
}
