#pragma once
// Scripted flights for `ussnav map`: lawnmower rows or an outward spiral over the world's free
// space at flight height, or waypoints from a CSV file; consecutive waypoints are joined by
// ground-truth shortest paths, so the flight is collision-free for the UAV's radius.

#include <filesystem>
#include <string>
#include <vector>

#include "ussnav/sim/gt_paths.hpp"

namespace ussnav {

// Rows `spacing` apart along x; each free run of a row contributes its two ends.
std::vector<Vec3> lawnmowerWaypoints(const GtPlanner& planner, double spacing);
// Archimedean spiral from `center` with `spacing` between turns, points every ~1 m that are free.
std::vector<Vec3> spiralWaypoints(const GtPlanner& planner, const Vec2& center, double spacing);
// CSV rows x,y,z; an optional header naming columns x, y and z reads them where they are
// (DIR/trajectory.csv from `explore`: t,x,y,z,yaw). Throws InputError on bad rows.
std::vector<Vec3> loadWaypointsCsv(const std::filesystem::path& path);
// Joins waypoints by shortest paths from `start`; unreachable waypoints are skipped (counted in
// `skipped` when given). Returns the whole polyline.
std::vector<Vec3> connectWaypoints(const GtPlanner& planner, const Vec3& start,
                                   const std::vector<Vec3>& waypoints, int* skipped = nullptr);

}  // namespace ussnav
