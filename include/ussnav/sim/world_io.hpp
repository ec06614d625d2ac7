#pragma once
// The versioned JSON world format (docs/world-format.md). saveWorld writes atomically;
// loadWorld validates everything and throws InputError naming the file and the field
// (e.g. "W.json: rooms[3].polygon: expected at least 3 points").

#include <filesystem>

#include <nlohmann/json.hpp>

#include "ussnav/sim/world.hpp"

namespace ussnav {

nlohmann::json worldToJson(const World& w);
// `source` names the input in error messages.
World worldFromJson(const nlohmann::json& j, const std::string& source = "<json>");
void saveWorld(const World& w, const std::filesystem::path& path);
World loadWorld(const std::filesystem::path& path);

// Semantic checks beyond the schema: rooms that overlap, objects outside every room, doors
// that do not join two rooms, ids not unique. Throws InputError(source, field, reason).
void validateWorld(const World& w, const std::string& source);

}  // namespace ussnav
