#pragma once
// Viewpoints of a frontier (paper Sec. V-A, FUEL's sampling): positions on rings of radius
// viewpoint_r_min..r_max around the centroid every viewpoint_dphi_deg at viewpoint_height,
// kept when in known free space with no occupied or unknown voxel within viewpoint_clearance;
// the yaw (every yaw_step_deg) that sees most of the frontier's cells wins, that count being
// the information gain. Visible: within sensor_range, inside the h/v field of view, and line
// of sight through the grid with unknown voxels blocking. Cost per frontier: positions x cells
// ray casts of up to sensor_range.

#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

struct Viewpoint {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;  // radians, the camera's heading
  int gain = 0;      // the frontier's cells visible from here with this yaw
};

// Whether frontier cell `key` is seen from `position` with heading `yaw` (see above).
bool cellVisible(const RollingGrid& grid, const Vec3& position, double yaw, const Vec3i& key,
                 const ExplorationConfig& cfg);

// Whether a viewpoint may stand at p: in the window, Free, no Occupied/Unknown voxel within
// viewpoint_clearance.
bool viewpointSafe(const RollingGrid& grid, const Vec3& p, const ExplorationConfig& cfg);

// Unknown volume (m^3) the camera at `position` with heading `yaw` looks into: rays over the
// field of view (every ~4 deg across, ~5 deg up) march the window in voxel steps up to
// sensor_range, stop at an occupied voxel or the window's edge, and integrate r^2 dr dOmega over
// unknown voxels whose centre z lies in [band_z_min, band_z_max]. Unknown does not block: what
// lies behind a frontier is what a viewpoint would reveal. Cost: ~300 rays x range / resolution.
double visibleUnknownVolume(const RollingGrid& grid, const Vec3& position, double yaw,
                            const ExplorationConfig& cfg);

// Viewpoints of the frontier made of `cells` (centroid `centroid`) with gain at least
// min_viewpoint_gain, best gain first (ties: sampling order), at most max_viewpoints.
std::vector<Viewpoint> computeViewpoints(const RollingGrid& grid, const std::vector<Vec3i>& cells,
                                         const Vec3& centroid, const ExplorationConfig& cfg);

}  // namespace ussnav
