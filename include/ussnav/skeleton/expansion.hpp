#pragma once
// The two steps of one iteration of Algorithm 1 (paper Sec. IV-A): ExpandNewPolyhedron (ray
// casting from a seed to Fibonacci-sphere points, then the convex hull) and FindNewExpandSeed
// (Nexus Point of a Boundary Surface, extended outwards along its normal, then validity checks).
// One expansion costs sphere_samples ray casts of at most max_radius plus one Qhull run.
//
// Unknown space: with skeleton.unknown_is_contact (default) a ray stops where unknown space
// begins, so polyhedra hold only observed free space and the faces facing unknown space become
// unknown-blocked Boundary Surfaces, retried when the map has grown there. A stretch of unknown
// voxels no longer than skeleton.max_unknown_gap with known free space behind it is a hole in
// the sensor data (sparse rays at range, dropouts), not unexplored space: rays pass it. Otherwise
// (unknown_is_contact false) rays pass all unknown voxels. The edge of the map window always
// stops a ray.

#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/boundary_surface.hpp"
#include "ussnav/skeleton/polyhedron.hpp"

namespace ussnav {

class ConnectivityGraph;

// Casts one ray per direction from `seed` up to cfg.max_radius and builds the hull of the end
// points. Obstacle rays end on the face of the blocking voxel. Invalid (faceless) polyhedron when
// the end points are degenerate (e.g. a seed inside an obstacle).
Polyhedron expandNewPolyhedron(const OccupancyMap& map, const Vec3& seed,
                               const std::vector<Vec3>& directions, const SkeletonConfig& cfg);

// Adaptive refinement (skeleton.refine_rays): the sphere's rays are ~0.5 rad apart, so where a hull
// face spans contact vertices (a wall corner, the wedge beside a door jamb, the space behind a
// chair leg) the free space between two rays is cut off. Up to cfg.refine_rays extra rays go from
// the seed through the centroids of the faces with a contact corner, largest faces first, in at
// most two rounds; an end point at least cfg.refine_min_gain outside its face joins the hull. The
// hull only grows (a superset of the base hull), so obstacles it newly cuts are recorded on the
// node like any other. Costs one ray cast per extra ray and one Qhull run per round.
Polyhedron refineHull(const OccupancyMap& map, Polyhedron poly, const Vec3& seed,
                      const SkeletonConfig& cfg);

// A hull of ray end points can cut the corner of an obstacle that lies between two rays (a door
// jamb, a table edge, a wall beside a door). A voxel counts as inside when its cube reaches more
// than kTouchFraction voxels into the hull (ray end points touch the voxels that stopped them).
constexpr double kTouchFraction = 0.1;
// Centres of the Occupied voxels of `map` inside `poly`, in key order. One state lookup per voxel
// of the hull's box.
std::vector<Vec3> obstacleVoxelsInside(const OccupancyMap& map, const Polyhedron& poly);
// With cfg.carve_obstacles, expandNewPolyhedron cuts them out of the hull: nearest to the seed
// first, each by the shallowest plane that keeps the seed (cutOutCube), so the hull stays convex.
// At most `max_cuts` cuts; a hull that needs more, or whose seed touches an obstacle, is returned
// invalid. Off by default: a convex hull cannot wrap a door jamb, and one plane per jamb costs
// ~5 points of free-space coverage (0.90 -> 0.85 on 9 worlds); nodes record the voxels instead.
Polyhedron carveObstacles(const OccupancyMap& map, Polyhedron poly, const Vec3& seed, int max_cuts);

enum class SeedStatus : uint8_t {
  Accepted,        // expand here
  TooClose,        // an existing node centre lies within min_center_distance: drop
  InsideExisting,  // inside an existing polyhedron: drop
  Unsafe,          // an obstacle within robot_radius, or no room to extend: drop
  Deferred,        // blocked by unknown space or outside the window: retry when `probe` is known
};
const char* seedStatusName(SeedStatus s);

struct SeedDecision {
  SeedStatus status = SeedStatus::Unsafe;
  Vec3 position = Vec3::Zero();  // the candidate seed
  Vec3 from = Vec3::Zero();      // start of the extension run (nexus or a free vertex)
  Vec3i probe = Vec3i::Zero();   // Deferred: the unknown voxel whose observation may change this
};

// FindNewExpandSeed: a ray from the Nexus Point along the surface normal, at most
// cfg.max_extension long, stopped by obstacles and (when unknown is contact) unknown space; the
// candidate is the middle of that free run, so the new polyhedron reaches back over the opening
// and forward to whatever ends the run. The candidate is then checked against the graph (too
// close to a centre, inside a polyhedron) and the map (in the window, robot_radius clearance).
// When that fails for a reason other than unknown space, up to cfg.seed_retries more runs start
// at the surface's free vertices (nearest the nexus first) along the owner's ray through them.
SeedDecision findNewExpandSeed(const BoundarySurface& surface, const OccupancyMap& map,
                               const ConnectivityGraph& graph, const SkeletonConfig& cfg);

// Walks from `from` to `to` like castRay, but: obstacles stop it; voxels outside the window stop
// it (hit_state Unknown); unknown voxels stop it only when `unknown_blocks` and the unknown
// stretch is longer than `max_gap` or runs to the end of the segment — then it stops where the
// stretch begins. The start voxel is not tested.
RayHit castRayThroughGaps(const OccupancyMap& map, const Vec3& from, const Vec3& to,
                          bool unknown_blocks, double max_gap);

// The first voxel within `radius` of p that is occupied (or unknown when unknown_unsafe), in a
// fixed scan order, an occupied one first; returns false when there is none (p is safe).
// `unknown_tolerated` unknown voxels are ignored (sensor holes, see max_unknown_gap).
bool findUnsafeVoxel(const OccupancyMap& map, const Vec3& p, double radius, bool unknown_unsafe,
                     Vec3i* key, VoxelState* state, int unknown_tolerated = 0);

}  // namespace ussnav
