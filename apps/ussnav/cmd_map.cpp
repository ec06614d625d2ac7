// `ussnav map`: fly a scripted trajectory in the simulator, run the scene-graph pipeline on
// every frame, and write DIR/map.png, DIR/scene_graph.json (docs/scene-graph-format.md) and
// DIR/stats.json (grid, coverage, skeleton, regions, objects, per-stage latency, and quality
// against ground truth).

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/image.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/episode/episode_drawing.hpp"
#include "ussnav/eval/map_quality.hpp"
#include "ussnav/eval/scene_quality.hpp"
#include "ussnav/mapping/map_drawing.hpp"
#include "ussnav/perception/oracle_detector.hpp"
#include "ussnav/pipeline/mapper.hpp"
#include "ussnav/scene_graph/drawing.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/scene_graph/viewer.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/trajectory.hpp"
#include "ussnav/sim/uav.hpp"
#include "ussnav/sim/world_io.hpp"
#include "ussnav/skeleton/graph_drawing.hpp"
#include "ussnav/skeleton/graph_metrics.hpp"

namespace ussnav::cli {
namespace {

struct MapArgs {
  std::string world, trajectory = "lawnmower", out = "out/map";
  bool skeleton = false;
  int max_frames = 0;
  double spacing = 2.5;
  uint64_t seed = 1;
};

void drawWorldOutline(Image& img, const TopDownView& view, const World& w) {
  for (const auto& wall : w.walls) {
    const Vec2 a = view.toPx(wall.a), b = view.toPx(wall.b);
    img.line(a.x(), a.y(), b.x(), b.y(), {205, 205, 215}, 2);
  }
}

void runMap(const MapArgs& a) {
  const Config& cfg = globals().config();
  World world = loadWorld(a.world);
  Simulator sim(world, cfg, a.seed);
  const GtPlanner& planner = sim.planner();
  const Pose start = sim.startPose();

  std::vector<Vec3> waypoints;
  if (a.trajectory == "lawnmower")
    waypoints = lawnmowerWaypoints(planner, a.spacing);
  else if (a.trajectory == "spiral")
    waypoints = spiralWaypoints(planner, start.position.head<2>(), a.spacing);
  else
    waypoints = loadWaypointsCsv(a.trajectory);
  int skipped = 0;
  const std::vector<Vec3> path = connectWaypoints(planner, start.position, waypoints, &skipped);
  progress("map: " + std::to_string(waypoints.size()) + " waypoints (" + std::to_string(skipped) +
           " unreachable), path " + std::to_string(int(GtPlanner::length(path))) + " m");
  progressDone();

  MapperOptions opt;
  opt.skeleton = a.skeleton;
  opt.objects = true;
  auto detector = std::make_unique<OracleDetector>(sim.instanceLabels(), OracleRealism::fromConfig(cfg.perception), a.seed);
  Mapper mapper(cfg, opt, std::move(detector));
  Uav uav(cfg.sim.uav, start);
  uav.setPath(path);
  const double dt = 1.0 / cfg.sim.frame_rate_hz;
  const double z = planner.flightZ();
  ObservedFreeSpace observed(cfg.mapping.grid.resolution, z - 0.25, z + 0.25);
  SeenInstances seen(cfg.perception.min_pixels);  // GT instances the camera saw (evaluation only)
  const Stopwatch wall;
  int frames = 0;
  double t = 0;
  std::vector<Vec3> flown{uav.pose().position};
  while (true) {
    SensedFrame f = sim.sense(uav.pose(), t);
    MapperFrame mf{f.pose, f.scan ? &*f.scan : nullptr, &f.depth, t};
    mapper.process(mf);
    observed.update(mapper.grid());
    seen.add(f.depth);
    ++frames;
    if (frames % 20 == 0 || uav.pathDone()) {
      char line[200];
      std::snprintf(line, sizeof line, "map: frame %d  t=%.0fs  flown %.1f/%.1f m  nodes %zu  update %.1f ms",
                    frames, t, uav.distanceTravelled(), GtPlanner::length(path), mapper.graph().size(),
                    mapper.times().median("update"));
      progress(line);
    }
    if (uav.pathDone() || (a.max_frames > 0 && frames >= a.max_frames)) break;
    uav.step(sim.groundTruth(), dt);
    flown.push_back(uav.pose().position);
    t += dt;
  }
  progressDone();

  // Stats.
  nlohmann::json stats;
  stats["world"] = a.world;
  stats["trajectory"] = a.trajectory;
  stats["frames"] = frames;
  stats["flight"] = {{"path_length_m", uav.distanceTravelled()}, {"collisions", uav.collisions()}, {"time_s", t}};
  stats["grid"] = {{"known_voxels", mapper.grid().knownVoxels()}, {"bytes", mapper.grid().memoryBytes()},
                   {"rejected_frames", mapper.grid().counters().rejected_frames},
                   {"invalid_points", mapper.grid().counters().invalid_points}};
  stats["coverage"] = {{"visited_cells", mapper.coverage().visitedCount()},
                       {"explored_area_m2", mapper.coverage().exploredArea()},
                       {"bytes", mapper.coverage().memoryBytes()},
                       {"bytes_per_m2", mapper.coverage().bytesPerExploredSquareMetre()}};
  if (a.skeleton) {
    const SkeletonQuality q = skeletonQuality(mapper.graph(), mapper.grid(), sim.groundTruth(), planner,
                                              observed, cfg.sim.uav.radius, 200, a.seed);
    nlohmann::json sk = toJson(graphStats(mapper.graph()));
    sk["free_space_coverage"] = q.free_space_coverage;
    sk["navigable_coverage"] = q.navigable_coverage;
    sk["path_success"] = q.path_success;
    sk["path_pairs"] = q.pairs;
    sk["observed_free_voxels"] = q.observed_free_voxels;
    sk["navigable_voxels"] = q.navigable_voxels;
    sk["mean_path_ratio"] = q.mean_path_ratio;
    sk["path_not_found"] = q.not_found;
    sk["path_colliding"] = q.colliding;
    stats["skeleton"] = sk;
  }
  const SceneGraph sg = buildSceneGraph(mapper, t, a.world);
  if (a.skeleton) {
    const RegionQuality rq = regionQuality(sg, world);
    stats["regions"] = {{"count", rq.count},           {"purity", rq.purity},
                        {"ari", rq.ari},               {"nodes_scored", rq.nodes_scored},
                        {"rooms_touched", rq.rooms_touched}, {"largest_share", rq.largest_share}};
  }
  if (const ObjectLayer* objs = mapper.objects()) {
    const std::unique_ptr<TextEncoder> encoder = makeTextEncoder(cfg.perception);
    const ObjectQuality oq = objectQuality(sg.objects, world, seen.ids(), encoder.get());
    stats["objects"] = {{"count", oq.count},
                        {"all", objs->objects().size()},
                        {"confirmed", objs->confirmedCount()},
                        {"absorbed", objs->absorbedCount()},
                        {"seen_instances", oq.seen_instances},
                        {"matched_objects", oq.matched_objects},
                        {"matched_instances", oq.matched_instances},
                        {"duplicates", oq.duplicates},
                        {"precision", oq.precision},
                        {"recall", oq.recall},
                        {"duplicate_rate", oq.duplicate_rate}};
  }
  stats["stage_ms"] = mapper.times().summary();
  stats["wall_s"] = wall.ms() / 1000.0;

  // Picture.
  const TopDownView view = TopDownView::fit(world.bounds(), 40.0);
  Image img(view.width, view.height, {235, 235, 235});
  drawCoverageMask(img, view, mapper.coverage());
  if (a.skeleton) drawRegions(img, view, sg);
  drawWorldOutline(img, view, world);
  drawGridSlice(img, view, mapper.grid(), z - 0.2, z + 0.2);
  if (a.skeleton) {
    GraphDrawOptions go;
    drawConnectivityGraph(img, view, mapper.graph(), go);
  }
  for (size_t i = 1; i < flown.size(); ++i) {  // the trajectory actually flown
    const Vec2 p = view.toPx(flown[i - 1]), q = view.toPx(flown[i]);
    img.line(p.x(), p.y(), q.x(), q.y(), {230, 60, 60}, 2);
  }
  if (const ObjectLayer* objs = mapper.objects())
    for (const auto& o : objs->objects()) {
      if (!o.confirmed) continue;
      const Vec2 p = view.toPx(o.centroid);
      img.fillCircle(p.x(), p.y(), 3, {150, 40, 160});
      img.text(int(p.x()) + 4, int(p.y()) - 3, o.label, {110, 20, 120});
    }
  const Vec2 s = view.toPx(start.position);
  img.fillCircle(s.x(), s.y(), 5, {0, 160, 0});
  img.text(8, 8, "ussnav map: " + std::filesystem::path(a.world).filename().string(), {0, 0, 0}, 2);

  std::filesystem::create_directories(a.out);
  writePng(std::filesystem::path(a.out) / "map.png", img);
  saveSceneGraph(std::filesystem::path(a.out) / "scene_graph.json", sg);
  ViewerOverlay ov = worldOverlay(world);
  ov.title = "ussnav map: " + std::filesystem::path(a.world).filename().string() + " (" + a.trajectory + ")";
  ov.trajectory = flown;
  writeSceneGraphHtml(std::filesystem::path(a.out) / "scene_graph.html", sg, ov);
  writeJsonAtomic(std::filesystem::path(a.out) / "stats.json", stats);

  std::printf("frames %d, flown %.1f m, collisions %d, known voxels %zu, grid %.1f MB, GCM visited %zu cells (%.0f m^2, %.0f B/m^2)\n",
              frames, uav.distanceTravelled(), uav.collisions(), mapper.grid().knownVoxels(),
              mapper.grid().memoryBytes() / 1e6, mapper.coverage().visitedCount(), mapper.coverage().exploredArea(),
              mapper.coverage().bytesPerExploredSquareMetre());
  if (a.skeleton)
    std::printf("skeleton: %d nodes, free-space coverage %.3f (navigable %.3f), path success %.3f (%d pairs)\n",
                stats["skeleton"]["nodes"].get<int>(), stats["skeleton"]["free_space_coverage"].get<double>(),
                stats["skeleton"]["navigable_coverage"].get<double>(),
                stats["skeleton"]["path_success"].get<double>(), stats["skeleton"]["path_pairs"].get<int>());
  if (a.skeleton)
    std::printf("regions: %d, the largest holds %.0f %% of the nodes, purity %.3f, ARI %.3f (%d nodes in rooms)\n",
                stats["regions"]["count"].get<int>(), 100.0 * stats["regions"]["largest_share"].get<double>(),
                stats["regions"]["purity"].get<double>(), stats["regions"]["ari"].get<double>(),
                stats["regions"]["nodes_scored"].get<int>());
  if (stats.contains("objects"))
    std::printf("objects: %d confirmed, precision %.3f, recall %.3f (%d seen instances), duplicate rate %.3f\n",
                stats["objects"]["count"].get<int>(), stats["objects"]["precision"].get<double>(),
                stats["objects"]["recall"].get<double>(), stats["objects"]["seen_instances"].get<int>(),
                stats["objects"]["duplicate_rate"].get<double>());
  for (const auto& [stage, v] : stats["stage_ms"].items())
    std::printf("  %-10s median %7.2f ms  p95 %7.2f ms\n", stage.c_str(), v["median"].get<double>(), v["p95"].get<double>());
  std::printf("wrote %s/map.png, scene_graph.json, scene_graph.html (open it in a browser) and stats.json\n",
              a.out.c_str());
}

void addMapCommand(CLI::App& root) {
  static MapArgs args;
  auto* cmd = root.add_subcommand("map", "Fly a scripted trajectory and build the scene graph; write map.png, scene_graph.json and stats.json");
  cmd->fallthrough();
  cmd->add_option("--world", args.world, "world JSON (ussnav world generate/import)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--trajectory", args.trajectory, "lawnmower | spiral | CSV file with x,y,z rows")->capture_default_str();
  cmd->add_option("--out", args.out, "output folder")->capture_default_str();
  cmd->add_flag("--skeleton", args.skeleton, "grow the Spatial Connectivity Graph and report its quality");
  cmd->add_option("--max-frames", args.max_frames, "stop after this many frames (0: whole trajectory)");
  cmd->add_option("--spacing", args.spacing, "lawnmower row / spiral turn spacing, m")->capture_default_str();
  cmd->add_option("--seed", args.seed, "seed for sensor noise and the detector")->capture_default_str();
  cmd->callback([] { runMap(args); });
}

}  // namespace
USSNAV_COMMAND(20, addMapCommand);
}  // namespace ussnav::cli
