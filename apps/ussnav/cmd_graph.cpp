// `ussnav graph show|view|stats`: read a saved scene graph (DIR/scene_graph.json from `ussnav map`
// or `explore`) and draw it, put it in a web page, or count its layers. Works on the document
// alone; `view` can add a world's ground truth and a flown trajectory.

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "ussnav/core/image.hpp"
#include "ussnav/scene_graph/drawing.hpp"
#include "ussnav/episode/episode_drawing.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/scene_graph/viewer.hpp"
#include "ussnav/sim/trajectory.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav::cli {
namespace {

struct ShowArgs {
  std::string file, out;
  double px_per_m = 30.0;
  bool coverage = false;
};

struct ViewArgs {
  std::string file, out, world, trajectory, title;
};

struct StatsArgs {
  std::string file;
  bool json = false;
};

void runShow(const ShowArgs& a) {
  const SceneGraph g = loadSceneGraph(a.file);
  const TopDownView view = TopDownView::fit(sceneBounds(g), a.px_per_m, 40);
  Image img(view.width, view.height, {245, 245, 245});
  SceneDrawOptions opt;
  opt.coverage = a.coverage;
  drawSceneGraph(img, view, g, opt);
  const SceneGraphCounts c = countLayers(g);
  const std::string title = "scene graph: " + std::to_string(c.nodes) + " nodes, " + std::to_string(c.edges) +
                            " edges, " + std::to_string(c.regions) + " regions, " + std::to_string(c.objects) +
                            " objects";
  img.text(8, 8, title, {0, 0, 0}, Image::textWidth(title, 2) + 16 <= view.width ? 2 : 1);
  writePng(a.out, img);
  std::printf("wrote %s (%d x %d px)\n", a.out.c_str(), view.width, view.height);
}

void runView(const ViewArgs& a) {
  const SceneGraph g = loadSceneGraph(a.file);
  ViewerOverlay ov;
  if (!a.world.empty()) ov = worldOverlay(loadWorld(a.world));
  if (!a.trajectory.empty()) ov.trajectory = loadWaypointsCsv(a.trajectory);
  ov.title = a.title;
  writeSceneGraphHtml(a.out, g, ov);
  const SceneGraphCounts c = countLayers(g);
  std::printf("wrote %s (%d nodes, %d regions, %d objects%s%s); open it in a browser\n", a.out.c_str(), c.nodes,
              c.regions, c.objects, a.world.empty() ? "" : ", the world's rooms and walls",
              a.trajectory.empty() ? "" : ", the trajectory");
}

void runStats(const StatsArgs& a) {
  const SceneGraph g = loadSceneGraph(a.file);
  const SceneGraphCounts c = countLayers(g);
  nlohmann::json j;
  j["file"] = a.file;
  j["source"] = g.source;
  j["time_s"] = g.time;
  j["nodes"] = c.nodes;
  j["edges"] = c.edges;
  j["edges_by_type"] = nlohmann::json::object();
  for (const auto& [t, n] : c.edges_by_type) j["edges_by_type"][t] = n;
  j["regions"] = c.regions;
  j["labelled_regions"] = c.labelled_regions;
  j["objects"] = c.objects;
  j["objects_by_label"] = nlohmann::json::object();
  for (const auto& [l, n] : c.objects_by_label) j["objects_by_label"][l] = n;
  j["coverage"] = {{"visited_cells", g.coverage.visited_cells}, {"explored_area_m2", g.coverage.explored_area_m2}};
  if (a.json) {
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("%s (%s, t=%.1f s)\n", a.file.c_str(), g.source.c_str(), g.time);
  std::printf("  nodes    %d\n  edges    %d (", c.nodes, c.edges);
  for (size_t i = 0; i < c.edges_by_type.size(); ++i)
    std::printf("%s%s %d", i ? ", " : "", c.edges_by_type[i].first.c_str(), c.edges_by_type[i].second);
  std::printf(")\n  regions  %d (%d labelled)\n  objects  %d\n", c.regions, c.labelled_regions, c.objects);
  for (const auto& [l, n] : c.objects_by_label) std::printf("    %-20s %d\n", l.c_str(), n);
  std::printf("  coverage %lld visited cells, %.1f m^2 explored\n", (long long)g.coverage.visited_cells,
              g.coverage.explored_area_m2);
}

void addGraphCommands(CLI::App& root) {
  auto* graph = subcommandGroup(root, "graph", "Inspect and draw saved scene graphs (scene_graph.json)");
  static ShowArgs show;
  auto* s = graph->add_subcommand("show", "Draw a saved scene graph top-down: regions, nodes, edges by type, objects");
  s->fallthrough();
  s->add_option("file", show.file, "scene_graph.json")->required()->check(CLI::ExistingFile);
  s->add_option("--out,-o", show.out, "PNG to write")->required();
  s->add_option("--px-per-m", show.px_per_m, "scale, pixels per metre")->capture_default_str()->check(CLI::Range(2.0, 200.0));
  s->add_flag("--coverage", show.coverage, "also shade the visited coverage cells");
  s->callback([] { runShow(show); });

  static ViewArgs view;
  auto* v = graph->add_subcommand(
      "view", "Write a saved scene graph as one self-contained web page: pan, zoom, layers, details on click, object search");
  v->fallthrough();
  v->add_option("file", view.file, "scene_graph.json")->required()->check(CLI::ExistingFile);
  v->add_option("--out,-o", view.out, "HTML file to write")->required();
  v->add_option("--world", view.world, "world JSON: also draw its rooms (with their types) and walls")->check(CLI::ExistingFile);
  v->add_option("--trajectory", view.trajectory, "CSV with x,y,z columns (DIR/trajectory.csv): also draw the flight")
      ->check(CLI::ExistingFile);
  v->add_option("--title", view.title, "page title (default: the graph's source)");
  v->callback([] { runView(view); });

  static StatsArgs st;
  auto* t = graph->add_subcommand("stats", "Counts per layer: nodes, edges by type, regions, objects by label, coverage");
  t->fallthrough();
  t->add_option("file", st.file, "scene_graph.json")->required()->check(CLI::ExistingFile);
  t->add_flag("--json", st.json, "one JSON object on stdout");
  t->callback([] { runStats(st); });
}

}  // namespace
USSNAV_COMMAND(30, addGraphCommands);
}  // namespace ussnav::cli
