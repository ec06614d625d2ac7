#include "ussnav/skeleton/boundary_surface.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <utility>

namespace ussnav {

FaceClass classifyFace(const Polyhedron& p, int face) {
  bool any_free = false, any_unknown = false;
  for (int v : p.faces[size_t(face)]) {
    const VertexKind k = p.kinds[size_t(v)];
    any_free |= k == VertexKind::Free;
    any_unknown |= k == VertexKind::Unknown;
  }
  if (any_free) return FaceClass::Opening;
  return any_unknown ? FaceClass::UnknownBlocked : FaceClass::Wall;
}

BoundarySurface makeBoundarySurface(const Polyhedron& p, std::vector<int> faces) {
  BoundarySurface s;
  s.faces = std::move(faces);
  Vec3 weighted_normal = Vec3::Zero(), weighted_centroid = Vec3::Zero();
  std::vector<int> verts;
  for (int f : s.faces) {
    const double a = p.faceArea(f);
    s.area += a;
    weighted_normal += a * p.normals[size_t(f)];
    weighted_centroid += a * p.faceCentroid(f);
    for (int v : p.faces[size_t(f)]) verts.push_back(v);
    s.unknown_blocked = classifyFace(p, f) == FaceClass::UnknownBlocked;
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (int v : verts) s.center += p.points[size_t(v)];
  if (!verts.empty()) s.center /= double(verts.size());
  if (s.area > 1e-12 && weighted_normal.norm() > 1e-9) {
    s.normal = weighted_normal.normalized();
    weighted_centroid /= s.area;
  } else {
    // Degenerate (zero-area) faces: fall back to the plain mean normal and the vertex mean.
    Vec3 n = Vec3::Zero();
    for (int f : s.faces) n += p.normals[size_t(f)];
    s.normal = n.norm() > 1e-9 ? Vec3(n.normalized()) : Vec3::UnitX();
    weighted_centroid = s.center;
  }
  s.nexus = s.center - (s.center - weighted_centroid).dot(s.normal) * s.normal;
  std::vector<std::pair<double, int>> free_verts;
  for (int v : verts)
    if (p.kinds[size_t(v)] == VertexKind::Free) free_verts.emplace_back((p.points[size_t(v)] - s.nexus).norm(), v);
  std::sort(free_verts.begin(), free_verts.end());
  for (const auto& fv : free_verts) s.free_vertices.push_back(p.points[size_t(fv.second)]);
  return s;
}

std::vector<BoundarySurface> findBoundarySurfaces(const Polyhedron& p, int max_faces,
                                                  double max_divergence_deg) {
  const int nf = int(p.faces.size());
  const size_t nfs = p.faces.size();
  std::vector<FaceClass> cls(nfs);
  for (int f = 0; f < nf; ++f) cls[size_t(f)] = classifyFace(p, f);

  // Face adjacency through shared edges (a closed triangulated hull: two faces per edge):
  // sort (edge, face) pairs and join neighbours with equal edges.
  std::vector<std::pair<int64_t, int>> edge_face;
  edge_face.reserve(nfs * 3);
  for (int f = 0; f < nf; ++f) {
    const auto& t = p.faces[size_t(f)];
    for (int i = 0; i < 3; ++i) {
      const int64_t a = t[size_t(i)], b = t[size_t((i + 1) % 3)];
      edge_face.emplace_back(std::min(a, b) * (int64_t(1) << 32) + std::max(a, b), f);
    }
  }
  std::sort(edge_face.begin(), edge_face.end());
  std::vector<std::vector<int>> adj(nfs);
  for (size_t i = 0; i < edge_face.size();) {
    size_t j = i;
    while (j < edge_face.size() && edge_face[j].first == edge_face[i].first) ++j;
    for (size_t u = i; u < j; ++u)
      for (size_t v = i; v < j; ++v)
        if (u != v) adj[size_t(edge_face[u].second)].push_back(edge_face[v].second);
    i = j;
  }
  for (auto& a : adj) std::sort(a.begin(), a.end());

  std::vector<int> order;
  for (int f = 0; f < nf; ++f)
    if (cls[size_t(f)] != FaceClass::Wall) order.push_back(f);
  std::vector<double> area(nfs);
  for (int f = 0; f < nf; ++f) area[size_t(f)] = p.faceArea(f);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return area[size_t(a)] > area[size_t(b)]; });

  const double cos_limit = std::cos(deg2rad(max_divergence_deg));
  std::vector<char> taken(nfs, 0);
  std::vector<BoundarySurface> out;
  for (int seed : order) {
    if (taken[size_t(seed)]) continue;
    const Vec3 seed_normal = p.normals[size_t(seed)];
    std::vector<int> cluster;
    std::deque<int> queue{seed};
    taken[size_t(seed)] = 1;
    while (!queue.empty() && int(cluster.size()) < max_faces) {
      const int f = queue.front();
      queue.pop_front();
      cluster.push_back(f);
      for (int g : adj[size_t(f)]) {
        if (taken[size_t(g)] || cls[size_t(g)] != cls[size_t(seed)]) continue;
        if (p.normals[size_t(g)].dot(seed_normal) < cos_limit) continue;
        taken[size_t(g)] = 1;
        queue.push_back(g);
      }
    }
    // Faces queued but not admitted (cluster full) stay free for a later cluster.
    for (int f : queue) taken[size_t(f)] = 0;
    out.push_back(makeBoundarySurface(p, std::move(cluster)));
  }
  return out;
}

}  // namespace ussnav
