#pragma once
// AWS RoboMaker Gazebo worlds (`aws_small_house/`, `aws_hospital/` in the shared data) -> a
// voxel World without rooms. The dataset's `objects.tsv` lists every model instance with its SDF
// pose and the world-frame box of its collision mesh. Wall models (`*Wall*`) are read from their
// COLLADA collision meshes (assimp, `<up_axis>` ignored as Gazebo does) and voxelised; floor and
// ceiling models are replaced by one-voxel slabs over the walls' footprint; inner doors are left
// open (removed) and doors on the building's outline stay shut (a "door" object); lights,
// cameras and cloth curtains are skipped; every other instance becomes an Object (collision box,
// or a nominal box for the Gazebo-Fuel models whose geometry is absent). The start pose is found as
// for scans (importers::chooseVoxelStart). Missing tables or meshes, bad rows -> InputError
// naming file and line or model. Cost: O(wall triangle area / voxel area).

#include <array>
#include <filesystem>
#include <vector>

#include "ussnav/core/types.hpp"
#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

// True when `path` is a Gazebo dataset this importer reads: a folder holding objects.tsv and a
// .world file, a .world file, or an objects.tsv with a .world beside it.
bool isGazeboDataset(const std::filesystem::path& path);

// Cells (size `res`, origin 0) that the triangles touch: every cell of a triangle's bounding
// box that a separating-axis test finds overlapping it (conservative: no ray slips between the
// cells of a closed surface). Sorted (z, y, x) and unique. Cost: the triangles' bounding boxes.
std::vector<Vec3i> voxeliseTriangles(const std::vector<std::array<Vec3, 3>>& triangles, double res);

World importGazeboWorld(const std::filesystem::path& path, const ImportOptions& opt = {}, ImportReport* report = nullptr);

}  // namespace ussnav
