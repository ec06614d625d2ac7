#pragma once
// The top-down picture of an episode (DIR/topdown.png): what the map knows at flight height
// (grey) and what the camera saw of it (green), the world's walls for reference, the scene
// graph (regions, edges, nodes, objects), the flown trajectory (red), the start (green dot),
// the goal's ground-truth instances (orange boxes) and the declared object (blue ring).
// Also the ground truth the web page (DIR/scene_graph.html, scene_graph/viewer.hpp) draws.

#include <vector>

#include "ussnav/core/image.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/exploration/camera_coverage.hpp"
#include "ussnav/scene_graph/viewer.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

Image drawEpisode(const World& world, const EpisodeRun& run, const CameraCoverage& camera,
                  const std::vector<const Object*>& goal_instances, const Pose& start);

// The world's rooms, its walls with the door openings (bottom below 0.3 m) cut out, and the
// footprints of `goal_instances`, for the web page; title and trajectory left empty.
ViewerOverlay worldOverlay(const World& world, const std::vector<const Object*>& goal_instances = {});

}  // namespace ussnav
