#pragma once
// Convex polyhedra of the Spatial Connectivity Graph (paper Sec. IV-A): the ray end points of one
// expansion, their convex hull (Qhull, triangulated), and the geometry later stages need —
// contains, intersects, volume, centroid. convexHull() costs one Qhull run (tens of microseconds
// for 50 points); the queries are O(faces) or O(faces * vertices).

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

// Triangulated convex hull of a point set. Faces index the input points and are ordered
// counter-clockwise seen from outside; planes are normal . x + offset = 0 with unit outward
// normals (inside: <= 0). Empty (no faces) when the input is degenerate: fewer than 4 points, all
// coplanar or collinear, or not finite.
struct ConvexHull {
  std::vector<std::array<int, 3>> faces;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  bool empty() const { return faces.empty(); }
};
ConvexHull convexHull(const std::vector<Vec3>& points);

// How the ray to a vertex ended: it reached the maximum radius (Free), or stopped at an
// occupied voxel (Obstacle) or at unknown space / the edge of the map window (Unknown). Obstacle
// and Unknown together are the paper's "contact" vertices.
enum class VertexKind : uint8_t { Free = 0, Obstacle = 1, Unknown = 2 };
inline bool isContact(VertexKind k) { return k != VertexKind::Free; }

struct Polyhedron {
  std::vector<Vec3> points;               // one per ray; some may lie inside the hull
  std::vector<VertexKind> kinds;          // parallel to points
  std::vector<std::array<int, 3>> faces;  // hull triangles, CCW from outside, into points
  std::vector<Vec3> normals;              // unit outward, per face
  std::vector<double> offsets;            // per face
  Vec3 centroid = Vec3::Zero();           // volume centroid of the hull
  double volume = 0.0;
  double radius = 0.0;                    // max distance from centroid to a hull vertex
  Aabb bounds;                            // of the hull vertices

  bool valid() const { return !faces.empty() && volume > 0.0; }
  // Inside or on the boundary (within `tolerance` metres of every face plane).
  bool contains(const Vec3& p, double tolerance = 1e-9) const;
  // Signed distance of p to the plane of face f (positive outside).
  double planeDistance(int f, const Vec3& p) const { return normals[size_t(f)].dot(p) + offsets[size_t(f)]; }
  Vec3 faceCentroid(int f) const;
  double faceArea(int f) const;
  // Indices of the points that are hull vertices, ascending.
  std::vector<int> hullVertices() const;
};

// Builds the polyhedron of `points` (with their kinds) through convexHull(); returns an invalid
// (faceless) polyhedron on degenerate input.
Polyhedron buildPolyhedron(std::vector<Vec3> points, std::vector<VertexKind> kinds);
// Same, from faces given by hand (CCW seen from outside): normals, offsets, volume, centroid and
// radius are computed. For tests and for callers that already have a hull.
Polyhedron makePolyhedron(std::vector<Vec3> points, std::vector<VertexKind> kinds,
                          std::vector<std::array<int, 3>> faces);

// The part of `p` with normal . x <= d (normal unit): hull vertices on that side plus the points
// where hull edges cross the plane (kind Obstacle: the cut lies against an obstacle), re-hulled.
// Invalid when nothing of volume is left. One Qhull run.
Polyhedron clipPolyhedron(const Polyhedron& p, const Vec3& normal, double d);

// How far the axis-aligned cube at c (half size h) reaches into p past every face plane: the
// smallest over faces of h |n|_1 - (n . c + offset). Positive when the cube crosses every face
// plane inward. Face-normal axes only, so a cube beside an edge of the hull may count as inside
// when it is not (callers then cut a little too much, never too little). O(faces).
double cubePenetration(const Polyhedron& p, const Vec3& c, double h);

// Cuts the voxel cube at c (half size h) out of p while keeping `keep` (the seed or centre): of
// the cube faces that face `keep` and the plane facing `keep` that touches the cube, the one
// whose cut is shallowest (least hull depth beyond it) — against a wall that is the wall's own
// plane, at a door jamb a slice off the corner. nullopt when no such plane keeps `keep`
// strictly inside; an invalid polyhedron when nothing of volume is left.
std::optional<Polyhedron> cutOutCube(const Polyhedron& p, const Vec3& c, double h, const Vec3& keep);

// Whether two convex polyhedra intersect (touching counts), by separating planes taken from the
// face normals of both. The edge-edge axes are not tested, so in rare configurations two
// disjoint polyhedra whose edges pass close to each other are reported as intersecting; it
// never misses a real intersection. Cost O((Fa + Fb) * (Va + Vb)) after a bounding-box check.
bool polyhedraIntersect(const Polyhedron& a, const Polyhedron& b, double tolerance = 1e-9);

}  // namespace ussnav
