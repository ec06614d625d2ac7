#pragma once
// Where to stand to declare a found object (DESIGN.md: within found_radius of the object's box,
// with it in view). Candidates around the mapped object's box — 24 directions, horizontal gaps
// of 0.2..0.8 m from the box side, at flight height and up to 0.6 m lower, or, only when none of
// those qualifies, kApproachAbove higher (a TV hung high on a wall) — are kept when the
// 3-D distance to the box is at most found_radius - found_margin, the pose is clear of
// obstacles and unknown space by episode.clearance in the map (UAV radius + 0.1 m when no pose
// keeps that), the box centre is inside
// the camera's field of view facing it (5 degrees inside the vertical half-angle), and the
// line of sight towards the box centre is not cut before reaching the box (the first occupied
// voxel on it, if any, meets the box: a wall the object stands against does not).
// Ranked by graph distance from the UAV. Pure function of the map and graph.

#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/exploration/graph_costs.hpp"
#include "ussnav/mapping/occupancy.hpp"

namespace ussnav {

struct ApproachPose {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;
  double cost_m = 0.0;  // graph distance from the UAV
};

// How far above flight height an approach pose may rise (the flight paths' waypoint band), m.
inline constexpr double kApproachAbove = 0.3;

// Distance from p to an axis-aligned box (0 inside).
double distanceToBox(const Aabb& box, const Vec3& p);

// Up to `max_poses` poses, cheapest first; empty when none qualifies.
std::vector<ApproachPose> approachPoses(const OccupancyMap& map, const GraphDistances& from_uav, const Aabb& box,
                                        double flight_z, const Config& cfg, int max_poses = 6);

}  // namespace ussnav
