#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ussnav/skeleton/boundary_surface.hpp"
#include "ussnav/skeleton/sphere_sampler.hpp"

using namespace ussnav;

namespace {

Polyhedron unitCube() {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return buildPolyhedron(pts, {});
}

// Faces of `p` whose normal is `n`.
std::vector<int> facesWithNormal(const Polyhedron& p, const Vec3& n) {
  std::vector<int> out;
  for (size_t f = 0; f < p.faces.size(); ++f)
    if (p.normals[f].dot(n) > 0.999) out.push_back(int(f));
  return out;
}

// A sphere of radius r at the origin with vertex kinds chosen by `kind(point)`.
template <class F>
Polyhedron sphere(double r, F kind) {
  std::vector<Vec3> pts;
  std::vector<VertexKind> kinds;
  for (const Vec3& d : fibonacciSphere(50)) {
    pts.push_back(d * r);
    kinds.push_back(kind(d * r));
  }
  return buildPolyhedron(pts, kinds);
}

double angleDeg(const Vec3& a, const Vec3& b) { return rad2deg(std::acos(std::clamp(a.dot(b), -1.0, 1.0))); }

}  // namespace

TEST(NexusPoint, TwoCubeFacesGiveThePointOnTheChamferPlane) {
  // Cluster = the +x and +y faces of the unit cube. Representative plane: normal (1,1,0)/sqrt2
  // through the area-weighted face centre (0.75, 0.75, 0.5). Geometric centre: mean of the six
  // distinct vertices, (2/3, 2/3, 1/2). Its projection onto the plane is (0.75, 0.75, 0.5).
  const Polyhedron cube = unitCube();
  std::vector<int> faces = facesWithNormal(cube, Vec3::UnitX());
  const std::vector<int> fy = facesWithNormal(cube, Vec3::UnitY());
  faces.insert(faces.end(), fy.begin(), fy.end());
  ASSERT_EQ(faces.size(), 4u);
  const BoundarySurface s = makeBoundarySurface(cube, faces);
  EXPECT_NEAR(s.area, 2.0, 1e-12);
  EXPECT_TRUE(s.center.isApprox(Vec3(2.0 / 3, 2.0 / 3, 0.5), 1e-12)) << s.center.transpose();
  EXPECT_TRUE(s.normal.isApprox(Vec3(1, 1, 0).normalized(), 1e-12)) << s.normal.transpose();
  EXPECT_TRUE(s.nexus.isApprox(Vec3(0.75, 0.75, 0.5), 1e-12)) << s.nexus.transpose();
}

TEST(NexusPoint, SingleFaceGivesItsCentroid) {
  const Polyhedron cube = unitCube();
  const std::vector<int> top = facesWithNormal(cube, Vec3::UnitZ());
  const BoundarySurface s = makeBoundarySurface(cube, {top[0]});
  EXPECT_TRUE(s.nexus.isApprox(cube.faceCentroid(top[0]), 1e-12));
  EXPECT_TRUE(s.normal.isApprox(Vec3::UnitZ(), 1e-12));
  EXPECT_NEAR(s.nexus.z(), 1.0, 1e-12);
}

TEST(NexusPoint, UnevenClusterProjectsOntoAreaWeightedPlane) {
  // +x face (area 1) and one triangle of the +z face (area 1/2): the plane normal leans 2:1
  // towards x and the nexus lies on that plane, between the two faces.
  const Polyhedron cube = unitCube();
  std::vector<int> faces = facesWithNormal(cube, Vec3::UnitX());
  faces.push_back(facesWithNormal(cube, Vec3::UnitZ())[0]);
  const BoundarySurface s = makeBoundarySurface(cube, faces);
  EXPECT_TRUE(s.normal.isApprox(Vec3(2, 0, 1).normalized(), 1e-12)) << s.normal.transpose();
  Vec3 plane_point = Vec3::Zero();
  double area = 0;
  for (int f : faces) {
    plane_point += cube.faceArea(f) * cube.faceCentroid(f);
    area += cube.faceArea(f);
  }
  plane_point /= area;
  EXPECT_NEAR((s.nexus - plane_point).dot(s.normal), 0.0, 1e-12);
  // The nexus differs from the centre only along the normal.
  EXPECT_NEAR((s.nexus - s.center).cross(s.normal).norm(), 0.0, 1e-12);
  EXPECT_GT((s.nexus - s.center).norm(), 1e-3);
}

TEST(BoundarySurfaces, ClassifiesWallsOpeningsAndUnknown) {
  const Polyhedron p = sphere(1.4, [](const Vec3& q) {
    if (q.z() < -0.5) return VertexKind::Obstacle;  // floor
    if (q.x() > 0.9) return VertexKind::Unknown;    // unobserved side
    return VertexKind::Free;
  });
  ASSERT_TRUE(p.valid());
  int walls = 0, openings = 0, unknown = 0;
  for (int f = 0; f < int(p.faces.size()); ++f) {
    const FaceClass c = classifyFace(p, f);
    bool any_free = false, all_obstacle = true;
    for (int v : p.faces[size_t(f)]) {
      any_free |= p.kinds[size_t(v)] == VertexKind::Free;
      all_obstacle &= p.kinds[size_t(v)] == VertexKind::Obstacle;
    }
    if (any_free) {
      EXPECT_EQ(c, FaceClass::Opening);
    }
    if (all_obstacle) {
      EXPECT_EQ(c, FaceClass::Wall);
    }
    walls += c == FaceClass::Wall;
    openings += c == FaceClass::Opening;
    unknown += c == FaceClass::UnknownBlocked;
  }
  EXPECT_GT(walls, 0);
  EXPECT_GT(openings, 0);
  EXPECT_GT(unknown, 0);

  const std::vector<BoundarySurface> surfaces = findBoundarySurfaces(p, 12, 45.0);
  std::set<int> seen;
  for (const BoundarySurface& s : surfaces) {
    ASSERT_FALSE(s.faces.empty());
    const FaceClass c0 = classifyFace(p, s.faces[0]);
    EXPECT_NE(c0, FaceClass::Wall);
    EXPECT_EQ(s.unknown_blocked, c0 == FaceClass::UnknownBlocked);
    for (int f : s.faces) {
      EXPECT_EQ(classifyFace(p, f), c0) << "a surface mixes face classes";
      EXPECT_TRUE(seen.insert(f).second) << "face " << f << " in two surfaces";
    }
    // Outward: the normal points away from the polyhedron centre.
    EXPECT_GT(s.normal.dot(s.nexus - p.centroid), 0.0);
  }
  EXPECT_EQ(int(seen.size()), openings + unknown);
}

TEST(BoundarySurfaces, SplitsOnFaceCountAndNormalDivergence) {
  const Polyhedron p = sphere(1.4, [](const Vec3&) { return VertexKind::Free; });
  ASSERT_EQ(p.faces.size(), 96u);
  // Without limits the whole sphere is one connected opening.
  EXPECT_EQ(findBoundarySurfaces(p, 1000, 180.0).size(), 1u);
  for (const auto& [max_faces, div] : {std::pair{12, 45.0}, std::pair{5, 90.0}, std::pair{1000, 30.0}}) {
    const std::vector<BoundarySurface> surfaces = findBoundarySurfaces(p, max_faces, div);
    size_t total = 0;
    for (const BoundarySurface& s : surfaces) {
      total += s.faces.size();
      EXPECT_LE(int(s.faces.size()), max_faces);
      for (int f : s.faces)
        EXPECT_LE(angleDeg(p.normals[size_t(f)], p.normals[size_t(s.faces[0])]), div + 1e-9);
    }
    EXPECT_EQ(total, 96u);
    EXPECT_GE(surfaces.size(), size_t(96 / max_faces));
    // A 30 degree cap holds a few faces only: many surfaces.
    if (div == 30.0) {
      EXPECT_GE(surfaces.size(), 12u);
    }
  }
}

TEST(BoundarySurfaces, ClustersAreEdgeConnected) {
  const Polyhedron p = sphere(1.4, [](const Vec3& q) { return q.y() > 0.3 ? VertexKind::Obstacle : VertexKind::Free; });
  for (const BoundarySurface& s : findBoundarySurfaces(p, 12, 45.0)) {
    // Flood fill over shared edges inside the cluster reaches every face.
    std::set<int> reached{s.faces[0]};
    bool grew = true;
    while (grew) {
      grew = false;
      for (int f : s.faces) {
        if (reached.count(f)) continue;
        for (int g : reached) {
          int shared = 0;
          for (int a : p.faces[size_t(f)])
            for (int b : p.faces[size_t(g)]) shared += a == b;
          if (shared == 2) {
            reached.insert(f);
            grew = true;
            break;
          }
        }
      }
    }
    EXPECT_EQ(reached.size(), s.faces.size());
  }
}
