#pragma once
// Short collision-free paths in an OccupancyMap: a bounded voxel A* (26-connected, only Free
// voxels, or Free and Unknown when unknown space is allowed) for the loop-closure edges of the
// Spatial Connectivity Graph, and line-of-sight shortcutting of polylines. The A* only visits
// voxels with g + h <= max_length, so its cost is bounded by the ellipsoid those span
// (a few thousand voxels for 3 m at 0.1 m).

#include <optional>
#include <span>
#include <vector>

#include "ussnav/mapping/occupancy.hpp"

namespace ussnav {

// Polyline from a to b (a and b included, corners shortcut by line of sight) of length at most
// `max_length`, or nullopt. The search runs on cells of `cell_voxels`^3 voxels, a cell passable
// when all its voxels are: 2 is several times cheaper and still passes any gap of 3 voxels
// (0.3 m at 0.1 m, less than a UAV of 0.25 m radius needs); 1 searches single voxels. The cells of a and b
// themselves need not be free; the result is always checked segment by segment on the voxels.
// The shortcuts keep a tube of `clearance` clear (see tubeOfSight).
std::optional<std::vector<Vec3>> gridPath(const OccupancyMap& map, const Vec3& a, const Vec3& b,
                                          double max_length, bool unknown_blocks = true,
                                          int cell_voxels = 1, double clearance = 0.0);

// Line of sight along a tube: the segment a-b and four copies of it moved `clearance` metres
// sideways (two perpendicular directions, both signs) are all unblocked (see castRay). A segment
// grazing the corner of an occupied voxel fails it; clearance 0 is plain lineOfSight.
bool tubeOfSight(const OccupancyMap& map, const Vec3& a, const Vec3& b, double clearance,
                 bool unknown_blocks);

// Greedy shortcutting: from each kept point jump to the farthest later point in tube of sight.
// Keeps the first and last point; never adds a segment that tubeOfSight reports blocked.
std::vector<Vec3> shortcutPolyline(const OccupancyMap& map, const std::vector<Vec3>& pts,
                                   bool unknown_blocks = true, double clearance = 0.0);

// Sum of segment lengths.
double polylineLength(const std::vector<Vec3>& pts);

// Whether every segment of the polyline is in tube of sight (see tubeOfSight).
bool polylineClear(const OccupancyMap& map, const std::vector<Vec3>& pts, bool unknown_blocks,
                   double clearance = 0.0);

// Whether a segment of the polyline comes within `radius` of one of `spots`.
bool polylinePassesNear(const std::vector<Vec3>& pts, std::span<const Vec3> spots, double radius);

}  // namespace ussnav
