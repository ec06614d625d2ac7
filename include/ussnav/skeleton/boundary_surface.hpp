#pragma once
// Boundary Surfaces (paper Sec. IV-A, "Growth Direction Analysis"): the faces of a polyhedron
// through which free space continues, clustered into surfaces that each give one growth
// direction, and their Nexus Point. Pure geometry on one polyhedron; O(faces).
//
// Which faces: the paper calls faces with heterogeneous (contact and free) vertices openings.
// With a 1.4 m radius in rooms larger than that, whole bands of faces have only free vertices
// (open space all round), so we count every face that has a free vertex as an opening, and a
// face whose vertices are all contact with at least one stopped by unknown space as an
// *unknown-blocked* opening (free space may continue once it is observed). Faces whose vertices
// all hit obstacles are walls and never grow.

#include <vector>

#include "ussnav/skeleton/polyhedron.hpp"

namespace ussnav {

enum class FaceClass : uint8_t { Wall = 0, Opening = 1, UnknownBlocked = 2 };
FaceClass classifyFace(const Polyhedron& p, int face);

struct BoundarySurface {
  int node = -1;              // owning graph node (-1 before the polyhedron joins the graph)
  std::vector<int> faces;     // indices into the owner's faces, all of one FaceClass
  bool unknown_blocked = false;
  double area = 0.0;
  Vec3 center = Vec3::Zero();  // mean of the cluster's distinct vertices (its geometric centre)
  Vec3 normal = Vec3::UnitX(); // area-weighted mean outward normal, unit
  Vec3 nexus = Vec3::Zero();   // center projected onto the representative plane
  std::vector<Vec3> free_vertices;  // the faces' Free vertices, nearest the nexus first (copies:
                                    // the owner's hull may be carved later)
};

// Fills area, center, normal and nexus of a surface made of `faces` of `p`. The representative
// plane has the area-weighted mean normal and passes through the area-weighted mean of the face
// centroids; the Nexus Point is the vertex mean projected onto it. Copies the Free vertices.
BoundarySurface makeBoundarySurface(const Polyhedron& p, std::vector<int> faces);

// Clusters the opening faces of `p` into Boundary Surfaces: region growing over faces that share
// an edge and have the same class, seeded from the largest unassigned face; a face joins only
// while the cluster has fewer than `max_faces` faces and its normal is within
// `max_divergence_deg` of the seed face's normal (the paper's split on size and on normal
// divergence). Deterministic. Surfaces come out in seeding order (largest seed face first).
std::vector<BoundarySurface> findBoundarySurfaces(const Polyhedron& p, int max_faces,
                                                  double max_divergence_deg);

}  // namespace ussnav
