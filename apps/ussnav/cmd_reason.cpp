// `ussnav goto` and `ussnav ask`: the extended capabilities on a saved scene graph (paper Sec.
// VI-B-3, reasoning/scene_queries.hpp). goto picks the region that serves a request and flies
// there in the simulator along the graph, without exploring; ask answers a question from the
// graph (regions, objects, layout). Region labels the graph lacks come from the reasoner.

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/episode/route_flight.hpp"
#include "ussnav/reasoning/reasoner.hpp"
#include "ussnav/reasoning/scene_queries.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/sim/simulator.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav::cli {
namespace {

struct ReasonArgs {
  std::string graph, world, request, question, at, from, out, reasoner;
};

Vec3 parsePoint(const std::string& s, const std::string& option) {
  std::stringstream ss(s);
  std::vector<double> v;
  for (std::string item; std::getline(ss, item, ',');) {
    try {
      size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size() || !std::isfinite(v.back())) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(option, "", "'" + s + "' is not a point; expected x,y or x,y,z in metres");
    }
  }
  if (v.size() != 2 && v.size() != 3) throw InputError(option, "", "'" + s + "' is not a point; expected x,y or x,y,z in metres");
  return Vec3(v[0], v[1], v.size() == 3 ? v[2] : 1.2);
}

struct Context {
  Config cfg;
  SceneGraph graph;
  std::shared_ptr<const CommonsensePriors> priors;
  std::shared_ptr<Reasoner> reasoner;
  std::map<int, RegionSemantics> semantics;
};

Context load(const ReasonArgs& a) {
  Context c;
  c.cfg = globals().config();
  if (!a.reasoner.empty()) c.cfg.reasoning.reasoner = a.reasoner;
  c.graph = loadSceneGraph(a.graph);
  if (c.graph.regions.empty()) throw InputError(a.graph, "regions", "the scene graph has no regions (map or explore first)");
  c.priors = CommonsensePriors::load(CommonsensePriors::defaultDir(), makeTextEncoder(c.cfg.perception));
  c.reasoner = makeReasoner(c.cfg.reasoning, c.priors);
  c.semantics = graphSemantics(c.graph, c.reasoner.get());
  return c;
}

void runGoto(const ReasonArgs& a) {
  Context c = load(a);
  const Instruction ins = interpretInstruction(a.request, *c.priors, graphVocabulary(c.graph));
  const RegionPick pick = pickRegionForRequest(c.graph, ins, c.semantics, *c.priors, c.cfg.episode.goal_similarity);
  std::printf("goto \"%s\": targets %s%s%s (%s)\n", a.request.c_str(), nlohmann::json(ins.targets).dump().c_str(),
              ins.room.empty() ? "" : (", room " + ins.room).c_str(),
              ins.room_hint.empty() ? "" : (", room hint " + ins.room_hint).c_str(), ins.how.c_str());
  std::printf("  chose %s (score %.2f)\n", pick.reason.c_str(), pick.score);

  const World world = loadWorld(a.world);
  Simulator sim(world, c.cfg, 1);
  Pose start = sim.startPose();
  if (!a.from.empty()) start.position = parsePoint(a.from, "--from");
  Vec3 goal = pick.goal;
  goal.z() = start.position.z();
  const auto route = routeOnSceneGraph(c.graph, start.position, goal);
  if (!route) throw InputError(a.graph, "edges", "no route on the graph from the start to region " + std::to_string(pick.region));
  // A matching object: stop short of it (found_radius - margin) on the last leg.
  std::vector<Vec3> path = *route;
  if (pick.object >= 0 && path.size() >= 2) {
    const Vec3 prev = path[path.size() - 2];
    const double keep = std::max(0.3, c.cfg.episode.found_radius - c.cfg.episode.found_margin);
    const Vec3 d = goal - prev;
    path.back() = d.norm() > keep ? Vec3(goal - d.normalized() * keep) : prev;
  }
  // The graph's route, flown on a live map (route_flight.hpp): the saved polyhedra reach the
  // faces of walls and furniture, so the legs between their centres are not flown blindly.
  const RouteFlight fl = flyRoute(sim, c.cfg, start, path);
  const int reached_region = regionAt(c.graph, fl.final_pose.position);
  const bool ok = fl.arrived && fl.collisions == 0;
  std::printf("  flew %.1f m in %.0f s along %zu graph waypoint%s (%d flight path%s): %s, now in region %d, %d collision%s\n",
              fl.path_length_m, fl.time_s, path.size(), path.size() == 1 ? "" : "s", fl.legs, fl.legs == 1 ? "" : "s",
              ok ? "ARRIVED" : ("STOPPED (" + fl.end_reason + ")").c_str(), reached_region, fl.collisions,
              fl.collisions == 1 ? "" : "s");
  if (fl.end_shift_m > 0.0)
    std::printf("  the goal point lay inside the clearance margin: stopped %.1f m short of it\n", fl.end_shift_m);
  if (!a.out.empty()) {
    nlohmann::json route_json = nlohmann::json::array();
    for (const Vec3& p : path) route_json.push_back({p.x(), p.y(), p.z()});
    writeJsonAtomic(a.out, {{"request", a.request},
                            {"targets", ins.targets},
                            {"region", pick.region},
                            {"object", pick.object},
                            {"reason", pick.reason},
                            {"route", route_json},
                            {"path_length_m", fl.path_length_m},
                            {"time_s", fl.time_s},
                            {"arrived", ok},
                            {"end_reason", fl.end_reason},
                            {"end", {fl.end.x(), fl.end.y(), fl.end.z()}},
                            {"flight_paths", fl.legs},
                            {"narrow_flight_paths", fl.narrow_legs},
                            {"blocked_flight_paths", fl.blocked},
                            {"remembered_obstacles", fl.remembered_obstacles},
                            {"final_region", reached_region},
                            {"collisions", fl.collisions}});
    std::printf("wrote %s\n", a.out.c_str());
  }
  if (!ok) throw std::runtime_error("the UAV did not arrive (" + fl.end_reason + ")");
}

void runAsk(const ReasonArgs& a) {
  Context c = load(a);
  std::optional<Vec3> at;
  if (!a.at.empty()) at = parsePoint(a.at, "--at");
  std::printf("%s\n", answerQuestion(c.graph, a.question, at, c.semantics, *c.priors).c_str());
}

void addReasonCommands(CLI::App& root) {
  static ReasonArgs g, q;
  auto* go = root.add_subcommand("goto", "Pick the region that serves a request from a saved scene graph and fly there");
  go->fallthrough();
  go->add_option("--graph", g.graph, "scene_graph.json (from ussnav explore or map)")->required()->check(CLI::ExistingFile);
  go->add_option("--world", g.world, "world JSON to fly in (the one the graph was built in)")->required()->check(CLI::ExistingFile);
  go->add_option("--request", g.request, "free text, e.g. \"I want to attend a meeting\"")->required();
  go->add_option("--from", g.from, "start point x,y[,z] (default: the world's start)");
  go->add_option("--out", g.out, "also write the decision and flight as JSON to this file");
  go->add_option("--reasoner", g.reasoner, "labels regions the graph lacks: builtin | llm")->check(CLI::IsMember({"builtin", "llm"}));
  go->callback([] { runGoto(g); });

  auto* ask = root.add_subcommand("ask", "Answer a question from a saved scene graph (regions, objects, layout)");
  ask->fallthrough();
  ask->add_option("--graph", q.graph, "scene_graph.json")->required()->check(CLI::ExistingFile);
  ask->add_option("--question", q.question,
                  "e.g. \"Describe the current area\", \"Where is the bed?\", \"What is in the kitchen?\", \"List all objects\", \"Describe the layout\"")
      ->required();
  ask->add_option("--at", q.at, "the current position x,y[,z] for questions about \"here\"");
  ask->add_option("--reasoner", q.reasoner, "labels regions the graph lacks: builtin | llm")->check(CLI::IsMember({"builtin", "llm"}));
  ask->callback([] { runAsk(q); });
}

}  // namespace
USSNAV_COMMAND(45, addReasonCommands);
}  // namespace ussnav::cli
