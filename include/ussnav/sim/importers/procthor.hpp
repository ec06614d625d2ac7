#pragma once
// ProcTHOR 1.0.0 house JSON -> World. Unity is y-up and left-handed with x east, z north, so
// (x, y, z)_unity -> (x, z, y) is the proper right-handed conversion (the plan reads as Unity's
// top view, not mirrored) and yaw = -rotation.y. Walls, listed once per side, are deduplicated
// and extruded; door holes become Openings; wall segments marked "empty" become doorless Doors;
// objects (and children) become boxes sized from the asset database. Linear in the file size.

#include <filesystem>

#include <nlohmann/json_fwd.hpp>

#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

// Throws InputError naming the file and JSON path on malformed input.
World importProcthorHouse(const std::filesystem::path& house_json, const ImportOptions& opt = {},
                          ImportReport* report = nullptr);

// True when `j` looks like a ProcTHOR house: rooms[] whose entries have a floorPolygon.
bool isProcthorHouse(const nlohmann::json& j);

}  // namespace ussnav
