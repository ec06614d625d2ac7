#pragma once
// Options shared by the world importers and the report each one fills: what was dropped or
// skipped and why, so the CLI can print it and tests can bound it. Plain data, no cost.

#include <filesystem>
#include <string>
#include <vector>

namespace ussnav {

struct ImportOptions {
  double flight_height = 1.2;            // start pose height above the floor, metres
  // ProcTHOR: walls are zero-thickness planes in the source; extruded this thick, centred.
  double wall_thickness = 0.1;
  // ProcTHOR asset sizes (asset_bboxes.tsv or asset-database.json); empty = look beside the
  // house folder (../asset_bboxes.tsv, then ../asset-database.json).
  std::filesystem::path asset_database;
  // Scans: voxel size (0 = the octree's own resolution; 0.1 m for point clouds and Gazebo wall
  // meshes) and the kept height band around the detected floor.
  double scan_resolution = 0.0;
  double scan_crop_below = 0.2;
  double scan_crop_above = 3.5;
};

struct ImportReport {
  std::string format;                  // "procthor", "webots", "scan", "gazebo"
  int source_objects = 0;              // object entries read from the input
  int dropped_objects = 0;             // objects whose centre lies outside every room
  int skipped_entries = 0;             // entries that are not objects (lights, sockets, ...)
  std::vector<std::string> warnings;   // one line each, meant for the user
  std::vector<std::string> notes;      // decisions taken from the data (floor height, ...)
};

}  // namespace ussnav
