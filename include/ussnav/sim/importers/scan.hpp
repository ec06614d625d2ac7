#pragma once
// Real 3D scans -> geometry-only World. The occupied voxels of an OctoMap (.bt, .ot) or the
// points of a PCD are voxelised into World::obstacles and cropped to a height band around the
// detected floor; there are no rooms and has_floor is false (the scan has its own floor and
// ceiling). The start pose is a free point at flight height, found automatically. Truncated or
// garbage files give InputError before liboctomap sees them. O(occupied voxels) time and memory.

#include <filesystem>
#include <vector>

#include "ussnav/core/types.hpp"
#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

// Points of a PCD v0.7 file with float32 fields x, y, z (others ignored), DATA binary or ascii.
// Non-finite points are skipped. Throws InputError on a bad header or a body shorter than POINTS.
std::vector<Vec3f> readPcdXyz(const std::filesystem::path& path);

// Centres of the occupied cells of an OctoMap file (.bt binary or .ot full OcTree) at the tree's
// finest resolution (pruned leaves are expanded), and that resolution.
struct OctreeVoxels {
  double resolution = 0.0;
  std::vector<Vec3f> centers;
};
OctreeVoxels readOctomapOccupied(const std::filesystem::path& path);

// .bt, .ot or .pcd -> World (see above). The start pose: among cells of the 2D projection that
// are free in the band floor+0.3 .. floor+flight_height+0.6 m and enclosed by occupied cells in
// all four axis directions, those with clearance >= min(best clearance, 1 m); of these the one
// nearest the centroid of the occupied cells (in an office floor: the corridor).
World importScan(const std::filesystem::path& path, const ImportOptions& opt = {}, ImportReport* report = nullptr);

}  // namespace ussnav
