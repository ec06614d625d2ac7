// `ussnav explore`: one ObjectNav episode in the simulator (episode/episode.hpp). Writes
// DIR/result.json, DIR/scene_graph.json, DIR/trajectory.csv and DIR/topdown.png.

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/episode/episode.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav::cli {
namespace {

struct ExploreArgs {
  std::string world, goal, planner = "full", out = "out/explore", reasoner;
  uint64_t seed = 1;
  double max_time = 0.0;
};

void runExplore(const ExploreArgs& a) {
  const Config& cfg0 = globals().config();
  Config cfg = cfg0;
  if (a.max_time > 0) cfg.episode.max_time_s = a.max_time;
  if (!a.reasoner.empty()) cfg.reasoning.reasoner = a.reasoner;
  EpisodeSpec spec;
  spec.world = loadWorld(a.world);
  spec.world_name = a.world;
  spec.goal = a.goal;
  spec.planner = a.planner;
  spec.seed = a.seed;
  makePlanner(a.planner);  // reject an unknown name before the simulator starts
  int last = -1;
  const EpisodeRun run = runEpisode(spec, cfg, [&](const EpisodeResult& r) {
    if (r.frames / 50 == last) return;
    last = r.frames / 50;
    char line[256];
    std::snprintf(line, sizeof line, "explore: t=%.0fs/%.0fs  frame %d  flown %.1f m  replans %d", r.time_s,
                  cfg.episode.max_time_s, r.frames, r.path_length_m, r.replans);
    progress(line);
  });
  progressDone();
  writeEpisode(a.out, run);
  const EpisodeResult& r = run.result;
  std::printf("explore %s: goal \"%s\", planner %s, seed %llu\n", a.world.c_str(), a.goal.c_str(), a.planner.c_str(),
              static_cast<unsigned long long>(a.seed));
  std::printf("  %s (%s): SPL %.3f, flown %.1f m, shortest %s m, %.0f s simulated, %d frames, %d collisions\n",
              r.success ? "SUCCESS" : "FAILURE", r.end_reason.c_str(), r.spl, r.path_length_m,
              r.shortest_path_m >= 0 ? std::to_string(r.shortest_path_m).substr(0, 5).c_str() : "n/a", r.time_s, r.frames,
              r.collisions);
  if (r.reasoning.contains("targets")) {
    std::printf("  instruction: targets %s%s (%s)", r.reasoning["targets"].dump().c_str(),
                r.reasoning.value("room", "").empty() ? "" : (" in the " + r.reasoning.value("room", "")).c_str(),
                r.reasoning.value("interpreted", "") == "functional"
                    ? "functional; an object seen is also judged against the request"
                    : r.reasoning.value("interpreted", "").c_str());
    if (r.reasoning.contains("decisions"))
      std::printf("; %s reasoner: %d decisions, %d fallbacks", r.reasoning.value("reasoner", "").c_str(),
                  r.reasoning.value("decisions", 0), r.reasoning.value("fallbacks", 0));
    std::printf("\n");
  }
  if (r.found_object)
    std::printf("  declared object %d \"%s\" at (%.2f, %.2f, %.2f)\n", r.found_object->id, r.found_object->label.c_str(),
                r.found_object->position.x(), r.found_object->position.y(), r.found_object->position.z());
  if (r.goal_instances == 0)
    std::printf("  note: the world holds no instance of \"%s\" (the episode cannot succeed)\n", a.goal.c_str());
  if (r.search_m >= 0) {
    std::printf("  goal first sighted at t=%.1f s after %.1f m", r.sighted_s, r.search_m);
    if (r.view_shortest_m >= 0) std::printf(" (the nearest view of it %.1f m from the start)", r.view_shortest_m);
    std::printf("; flown after it %.1f m", std::max(0.0, r.path_length_m - r.search_m));
    if (r.approach_shortest_m >= 0) std::printf(" (shortest from there %.1f m)", r.approach_shortest_m);
    std::printf("\n");
  }
  const auto many = [](size_t n) { return n == 1 ? "" : "s"; };
  std::printf("  scene graph: %zu node%s, %zu region%s, %zu object%s; camera saw %.0f of %.0f m^2 known\n",
              run.graph.nodes.size(), many(run.graph.nodes.size()), run.graph.regions.size(),
              many(run.graph.regions.size()), run.graph.objects.size(), many(run.graph.objects.size()),
              r.coverage.empty() ? 0.0 : r.coverage.back().camera_seen_m2, r.coverage.empty() ? 0.0 : r.coverage.back().known_m2);
  if (r.region_count > 0) {
    std::printf("  regions (against ground truth): the largest holds %.0f %% of the nodes", 100.0 * r.region_largest_share);
    if (r.region_ari > -1.0) std::printf("; ARI %.3f against the world's rooms", r.region_ari);
    std::printf("\n");
  }
  if (r.labels_scored > 0)
    std::printf("  region labels (against ground truth): %d of %d correct\n", r.labels_correct, r.labels_scored);
  std::printf("  per-frame update: median %.2f ms (%.0f Hz), wall %.1f s\n", 1000.0 / std::max(r.update_hz, 1e-9),
              r.update_hz, r.wall_s);
  std::printf("wrote %s/result.json, scene_graph.json, scene_graph.html (open it in a browser), trajectory.csv, topdown.png\n", a.out.c_str());
}

void addExploreCommand(CLI::App& root) {
  static ExploreArgs args;
  auto* cmd = root.add_subcommand("explore", "Run one ObjectNav episode: explore a world until the goal object is found");
  cmd->fallthrough();
  cmd->add_option("--world", args.world, "world JSON (ussnav world generate/import)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--goal", args.goal,
                  "what to find, in free text: \"bed\", \"somewhere to sleep\", \"the sofa in the living room\"")
      ->required();
  cmd->add_option("--planner", args.planner, "full | frontier | tsp")->capture_default_str();
  cmd->add_option("--reasoner", args.reasoner, "coarse level of `full`: builtin | llm | oracle (ground truth, an upper bound) | oracle-labels (the true room types, the builtin rule); default: reasoning.reasoner")
      ->check(CLI::IsMember({"builtin", "llm", "oracle", "oracle-labels"}));
  cmd->add_option("--seed", args.seed, "seed for sensor noise and the detector")->capture_default_str();
  cmd->add_option("--max-time", args.max_time, "time budget in simulated seconds (default: episode.max_time_s)");
  cmd->add_option("--out", args.out, "output folder")->capture_default_str();
  cmd->callback([] { runExplore(args); });
}

}  // namespace
USSNAV_COMMAND(40, addExploreCommand);
}  // namespace ussnav::cli
