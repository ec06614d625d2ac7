#pragma once
// Where to stand to declare a found object (DESIGN.md: within found_radius of the object's box,
// with it in view). Candidates around the mapped object's box — 24 directions, horizontal gaps
// of 0.2..0.8 m from the box side, at flight height and up to 0.6 m lower, or, only when none of
// those qualifies, kApproachAbove higher (a TV hung high on a wall) — are kept when the
// 3-D distance to the box is at most found_radius - found_margin, the pose is clear of
// obstacles and unknown space by episode.clearance in the map (UAV radius + 0.1 m when no pose
// keeps that), the box centre is inside
// the camera's field of view facing it (5 degrees inside the vertical half-angle), and the
// line of sight towards the box centre is not cut before reaching the box (seesBox with unknown
// space passing: the first occupied voxel on it, if any, meets the box; a wall the object stands
// against does not). Space not seen yet does not cut it: in front of a fridge at the end of a
// narrow kitchen, or below a TV hung high, the map often has not seen every voxel when the pose
// is chosen (requiring it left house_6 "fridge" without a pose for 200 s). The episode declares
// only what the detector then sees from the pose, so a pose behind an unseen wall costs a flight,
// not a wrong find.
// Ranked by graph distance from the UAV. Pure function of the map and graph.

#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/exploration/graph_costs.hpp"
#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

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

// Whether the line of sight from p towards the box centre reaches the box: nothing blocks it, or
// the first blocking voxel is an occupied one that meets the box (the object's surface, as the
// sensors saw it). Unknown voxels block when `unknown_blocks`: an unseen voxel next to the box may
// be the foot of the wall it stands against, seen from the wrong side.
bool seesBox(const OccupancyMap& map, const Vec3& p, const Vec3& box_center, const Aabb& box, bool unknown_blocks);

// Where to fly for a closer look at an object no approach pose is found for yet (seen from afar,
// through a door): the graph node within `radius` of `centroid` nearest to it whose centre, at
// flight height, sees the box through space seen free (seesBox); else, the map around the object
// being what is missing, the node nearest to `centroid`. The nearest node may be on the other
// side of the wall the object stands against, no place to look from: nodes within 1 m (in plan)
// of a point in `avoid` (where a transit already ended with no approach pose) are not chosen,
// unless no other node is left. Given `seen_from` (where the camera saw the object), when no
// node within `radius` sees the box (the space around it beyond the rolling window, or
// forgotten), the nearest of them within 0.75 m (in plan) of the line of sight from `seen_from`
// to `centroid` comes first: the side of the walls it was seen from (house_6 "fridge":
// transits again and again to a node behind the kitchen wall, 0.8 m from the fridge seen from
// 5 m down the kitchen). -1 on an empty graph.
int transitNode(const ConnectivityGraph& graph, const OccupancyMap& map, const Aabb& box, const Vec3& centroid,
                double flight_z, double radius, const std::vector<Vec3>& avoid = {},
                const Vec3* seen_from = nullptr);

// Up to `max_poses` poses, cheapest first; empty when none qualifies.
std::vector<ApproachPose> approachPoses(const OccupancyMap& map, const GraphDistances& from_uav, const Aabb& box,
                                        double flight_z, const Config& cfg, int max_poses = 6);

}  // namespace ussnav
