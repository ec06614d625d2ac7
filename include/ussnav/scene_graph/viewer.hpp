#pragma once
// The scene graph in a web page: one self-contained HTML file (no network, no external script;
// open it in any browser) that draws a SceneGraph top-down with pan and zoom, layers to toggle
// (regions, polyhedra, edges by type, objects, coverage, and an optional overlay: the
// trajectory, the ground-truth rooms and walls, the goal instances), a click for a node's,
// region's or object's details, and an object search. The page embeds a compact view of the
// document (x-y footprints rounded to 1 cm), not the document itself: a saved scene_graph.json
// stays the exact record. Cost: O(nodes * V log V + edges + objects).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/scene_graph/scene_graph.hpp"

namespace ussnav {

// What the page draws besides the graph; every part optional (empty: not drawn, no toggle).
struct ViewerOverlay {
  std::string title;                          // page title (default: the graph's source)
  struct Room {
    int id = -1;
    std::string type;
    std::vector<Vec2> polygon;
  };
  std::vector<Room> rooms;                    // ground truth, for comparing regions with rooms
  std::vector<std::pair<Vec2, Vec2>> walls;   // wall segments, door openings cut out
  struct Goal {
    int id = -1;
    std::string category;
    std::vector<Vec2> footprint;
  };
  std::vector<Goal> goals;                    // ground-truth goal instances
  std::vector<Vec3> trajectory;               // the UAV's flight, drawn as a line with its start
  nlohmann::json episode;                     // key facts shown in the side panel (null: none)
};

// The data the page embeds (format "ussnav-viewer", version 1; what the page's script reads).
nlohmann::json viewerData(const SceneGraph& g, const ViewerOverlay& overlay = {});
// The whole page. The embedded JSON has every '<' escaped, so no label can end the script.
std::string sceneGraphHtml(const SceneGraph& g, const ViewerOverlay& overlay = {});
// Writes the page atomically.
void writeSceneGraphHtml(const std::filesystem::path& path, const SceneGraph& g, const ViewerOverlay& overlay = {});

}  // namespace ussnav
