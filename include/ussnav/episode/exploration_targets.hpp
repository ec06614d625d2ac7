#pragma once
// The targets a re-plan of the flight loop chooses among (the planners' input, exploration/
// planner.hpp): every frontier the TargetMemory does not skip, with its viewpoints, and every
// camera-unseen patch with a viewpoint. Two kinds of frontier get a stand-in viewpoint at the
// graph node nearest to them, at flight height, facing them:
//  - one reached once and still open (close_look: a room seen through its door), unless that
//    node is where the UAV already looked from (then it is skipped for good);
//  - one with no viewpoint (found at the rolling window's edge), when that node is within 3 m,
//    at half its cell count: from there the window covers it again.
// Gains in the planners' unit (planner.hpp). Target regions are left for the caller to set.

#include <optional>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/episode/search_memory.hpp"
#include "ussnav/exploration/camera_coverage.hpp"
#include "ussnav/exploration/frontier.hpp"
#include "ussnav/exploration/planner.hpp"
#include "ussnav/mapping/rolling_grid.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

// A viewpoint at the graph node nearest to c, at height z, facing c, with this gain; none on an
// empty graph.
std::optional<Viewpoint> nodeFacing(const ConnectivityGraph& graph, const Vec3& c, double z, int gain);

// `debug`: say on stderr why a frontier is skipped.
std::vector<ExplorationTarget> collectTargets(const FrontierFinder& frontiers, const std::vector<UnseenPatch>& patches,
                                              TargetMemory& memory, double t, const ConnectivityGraph& graph,
                                              const RollingGrid& grid, const ExplorationConfig& cfg, bool close_look,
                                              double flight_z, bool debug);

}  // namespace ussnav
