#pragma once
// Top-down pictures of the mapping layers: the rolling grid as a horizontal slice (unknown grey,
// free white, occupied black) and the Global Coverage Mask (visited cells tinted green, cells
// that were ever seen tinted grey). O(window voxels in the slice + allocated cells).

#include "ussnav/core/image.hpp"
#include "ussnav/mapping/coverage_mask.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

// Max-projection over [z_min, z_max]: occupied wins over free, free over unknown.
void drawGridSlice(Image& img, const TopDownView& view, const RollingGrid& grid, double z_min, double z_max);
void drawCoverageMask(Image& img, const TopDownView& view, const CoverageMask& mask);

}  // namespace ussnav
