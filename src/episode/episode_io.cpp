#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "ussnav/core/io.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/scene_graph/viewer.hpp"

namespace ussnav {

nlohmann::json toJson(const EpisodeResult& r) {
  nlohmann::json j;
  j["world"] = r.world;
  j["goal"] = r.goal;
  j["planner"] = r.planner;
  j["seed"] = r.seed;
  j["success"] = r.success;
  j["spl"] = r.spl;
  j["path_length_m"] = r.path_length_m;
  j["shortest_path_m"] = r.shortest_path_m >= 0 ? nlohmann::json(r.shortest_path_m) : nlohmann::json(nullptr);
  j["time_s"] = r.time_s;
  j["frames"] = r.frames;
  j["collisions"] = r.collisions;
  if (r.found_object)
    j["found_object"] = {{"id", r.found_object->id},
                         {"label", r.found_object->label},
                         {"position", {r.found_object->position.x(), r.found_object->position.y(), r.found_object->position.z()}}};
  else
    j["found_object"] = nullptr;
  j["end_reason"] = r.end_reason;
  j["goal_instances"] = r.goal_instances;
  j["split"] = r.multi_room ? "multi_room" : "single_room";
  j["replans"] = r.replans;
  j["unreachable_targets"] = r.unreachable;
  j["close_looks"] = r.close_looks;
  j["flight_paths"] = {{"planned", r.paths_planned}, {"narrow_margin", r.paths_narrow},
                       {"through_unknown", r.paths_through_unknown}, {"remembered_obstacles", r.remembered_obstacles},
                       {"past_remembered", r.paths_past_remembered}};
  j["update_hz"] = r.update_hz;
  j["stage_ms"] = r.stage_ms;
  j["reasoning"] = r.reasoning;
  j["reasoner_fallbacks"] = r.reasoner_fallbacks;
  j["view_shortest_m"] = r.view_shortest_m >= 0 ? nlohmann::json(r.view_shortest_m) : nlohmann::json(nullptr);
  if (r.search_m >= 0)
    j["sighting"] = {{"t_s", r.sighted_s},
                     {"search_m", r.search_m},
                     {"approach_m", std::max(0.0, r.path_length_m - r.search_m)},
                     {"approach_shortest_m", r.approach_shortest_m >= 0 ? nlohmann::json(r.approach_shortest_m) : nlohmann::json(nullptr)}};
  else
    j["sighting"] = nullptr;
  j["region_labels"] = r.region_labels.is_null() ? nlohmann::json::object() : r.region_labels;
  j["regions"] = r.regions.is_null() ? nlohmann::json::object() : r.regions;
  nlohmann::json cov = nlohmann::json::array();
  for (const CoverageSample& c : r.coverage) cov.push_back({{"t", c.t}, {"known_m2", c.known_m2}, {"camera_seen_m2", c.camera_seen_m2}});
  j["coverage"] = cov;
  if (!r.coverage.empty()) {
    j["known_area_m2"] = r.coverage.back().known_m2;
    j["camera_seen_area_m2"] = r.coverage.back().camera_seen_m2;
  }
  j["wall_s"] = r.wall_s;
  return j;
}

void writeEpisode(const std::string& dir, const EpisodeRun& run) {
  const std::filesystem::path d(dir);
  std::filesystem::create_directories(d);
  std::ostringstream csv;
  csv << "t,x,y,z,yaw\n";
  char line[160];
  for (const TrajectorySample& s : run.trajectory) {
    std::snprintf(line, sizeof line, "%.2f,%.3f,%.3f,%.3f,%.4f\n", s.t, s.pose.position.x(), s.pose.position.y(),
                  s.pose.position.z(), s.pose.yaw);
    csv << line;
  }
  writeFileAtomic(d / "trajectory.csv", csv.str());
  saveSceneGraph(d / "scene_graph.json", run.graph);
  ViewerOverlay ov = run.overlay;
  ov.title = run.result.world + ": " + run.result.goal + " (" + run.result.planner + ")";
  for (const TrajectorySample& s : run.trajectory) ov.trajectory.push_back(s.pose.position);
  const nlohmann::json r = toJson(run.result);
  ov.episode = nlohmann::json::object();
  for (const char* k : {"world", "goal", "planner", "seed", "success", "spl", "path_length_m", "shortest_path_m",
                        "time_s", "end_reason", "found_object", "split"})
    ov.episode[k] = r[k];
  if (r["reasoning"].is_object() && r["reasoning"].contains("choices")) ov.episode["choices"] = r["reasoning"]["choices"];
  writeSceneGraphHtml(d / "scene_graph.html", run.graph, ov);
  writePng(d / "topdown.png", run.topdown);
  writeJsonAtomic(d / "result.json", toJson(run.result));  // last: its presence marks a complete run
}

}  // namespace ussnav
