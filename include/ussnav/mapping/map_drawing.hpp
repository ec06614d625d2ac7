#pragma once
// Top-down pictures of the mapping layers: the rolling grid as a horizontal slice (unknown grey,
// free white, occupied black) and the Global Coverage Mask (visited cells tinted green, cells
// that were ever seen tinted grey). O(window voxels in the slice + allocated cells).

#include <string>
#include <vector>

#include "ussnav/core/image.hpp"
#include "ussnav/mapping/coverage_mask.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

// Max-projection over [z_min, z_max]: occupied wins over free, free over unknown.
void drawGridSlice(Image& img, const TopDownView& view, const RollingGrid& grid, double z_min, double z_max);
void drawCoverageMask(Image& img, const TopDownView& view, const CoverageMask& mask);

// The window's voxel layer at height z as text, one row per y (highest first), for debugging:
// '#' occupied, '.' free, ' ' unknown; ',' free and 'u' unknown in a visited coverage cell; 'F'
// a voxel whose x-y column holds a cell of `marked` (frontier cells, say). A header line names
// the window's keys.
std::string asciiSlice(const RollingGrid& grid, const CoverageMask& mask, const std::vector<Vec3i>& marked, double z);

}  // namespace ussnav
