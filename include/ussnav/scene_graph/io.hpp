#pragma once
// JSON form of the SceneGraph document (docs/scene-graph-format.md, format
// "ussnav-scene-graph", schema_version 1). save is atomic; load validates everything and
// throws InputError(file, field, what) naming the exact field ("edges[3].b") on missing keys,
// wrong types, non-finite numbers, duplicate ids and references to unknown nodes / regions.
// A saved document loads back equal (doubles are written round-trip exact). O(size).

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "ussnav/scene_graph/scene_graph.hpp"

namespace ussnav {

nlohmann::json toJson(const SceneGraph& g);
// `source` names the input in error messages.
SceneGraph sceneGraphFromJson(const nlohmann::json& j, const std::string& source = "scene graph");

void saveSceneGraph(const std::filesystem::path& path, const SceneGraph& g);
SceneGraph loadSceneGraph(const std::filesystem::path& path);

}  // namespace ussnav
