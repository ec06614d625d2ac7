#pragma once
// Which region an object seen beyond a region leads to. summarizeRegions() lists an object the
// observing region's nodes do not reach as that region's `beyond` (a bed seen through a door):
// the builtin reasoner reads it as evidence about the room next door, reached through this
// region's frontiers. But the observing region's frontiers may lead elsewhere (apartment-72
// "bed", session 48: seen from the kitchen through the hallway's door, it raised the kitchen,
// whose frontiers lead away from it). facingFrontierRegions() moves each such object to the
// region of the frontier that faces it: the frontier target nearest to it in the plane whose
// straight line to the object's box crosses no occupied voxel and runs through known-free space
// for at least `min_free` of its length (the space the camera saw on its way to the object,
// not a guess through an unseen wall). With no such frontier the object stays where it was.

#include <vector>

#include "ussnav/exploration/planner.hpp"
#include "ussnav/mapping/occupancy.hpp"
#include "ussnav/reasoning/region_semantics.hpp"

namespace ussnav {

// The frontier target in `targets` that faces `o` (see above), or -1. Only frontiers with a
// region count; unseen patches lie inside known space and lead nowhere new.
int frontierFacing(const ObjectBrief& o, const std::vector<ExplorationTarget>& targets, const OccupancyMap& map,
                   double min_free = 0.5);

// Moves every beyond object whose facing frontier lies in another region of `regions` to that
// region's `beyond` list (ascending object id there). Returns how many moved.
int facingFrontierRegions(std::vector<RegionSummary>& regions, const std::vector<ExplorationTarget>& targets,
                          const OccupancyMap& map, double min_free = 0.5);

}  // namespace ussnav
