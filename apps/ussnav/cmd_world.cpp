// `ussnav world generate|render|stats|categories`: make a furnished floor plan from a seed,
// draw a world top-down, summarise it, list the object table. (`world import` lives in its own
// file and joins the same group.)

#include <iomanip>
#include <iostream>

#include "command.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/object_table.hpp"
#include "ussnav/sim/world_io.hpp"
#include "ussnav/sim/world_render.hpp"
#include "ussnav/sim/world_stats.hpp"

namespace ussnav::cli {
namespace {

struct GenerateArgs {
  std::string style = "office";
  int64_t seed = 1;
  int rooms = 0;
  double area = 0.0;
  std::string out;
  bool no_objects = false;
};

struct RenderArgs {
  std::string world, out;
  double px_per_m = 30.0;
  bool no_labels = false;
};

struct StatsArgs {
  std::string world;
  bool json = false;
};

void runGenerate(const GenerateArgs& a) {
  if (a.seed < 0) throw InputError("world generate", "--seed", "expected a non-negative integer");
  const Config& cfg = globals().config();
  GeneratorParams p;
  p.style = a.style;
  p.seed = uint64_t(a.seed);
  p.target_rooms = a.rooms;
  p.target_area_m2 = a.area;
  p.flight_height = cfg.sim.uav.flight_height;
  p.uav_radius = cfg.sim.uav.radius;
  p.furnish = !a.no_objects;
  Stopwatch sw;
  const World w = generateWorld(p);
  const double ms = sw.ms();
  validateWorld(w, a.out);
  saveWorld(w, a.out);
  const WorldStats s = computeWorldStats(w);
  std::cout << "wrote " << a.out << ": " << w.name << ", " << s.rooms << " rooms, " << s.doors << " doors, "
            << s.objects << " objects, " << std::fixed << std::setprecision(1) << s.floor_area_m2
            << " m^2 floor, generated in " << ms << " ms\n";
}

void runRender(const RenderArgs& a) {
  const World w = loadWorld(a.world);
  RenderOptions o;
  o.px_per_m = a.px_per_m;
  o.object_labels = !a.no_labels;
  const Image img = renderWorld(w, o);
  writePng(a.out, img);
  std::cout << "wrote " << a.out << " (" << img.width() << " x " << img.height() << " px)\n";
}

void runStats(const StatsArgs& a) {
  const WorldStats s = computeWorldStats(loadWorld(a.world));
  if (a.json)
    std::cout << worldStatsToJson(s).dump() << "\n";
  else
    std::cout << worldStatsToText(s);
}

void addWorldCommands(CLI::App& root) {
  auto* world = subcommandGroup(root, "world", "Create, import, inspect and draw worlds");

  static GenerateArgs gen;
  auto* g = world->add_subcommand("generate",
                                  "Generate a furnished floor plan from a seed (same seed, same file)");
  g->fallthrough();
  g->add_option("--style", gen.style, "office (corridors, offices, meeting rooms...) or apartment")
      ->capture_default_str();
  g->add_option("--seed", gen.seed, "random seed")->capture_default_str();
  g->add_option("--rooms", gen.rooms, "number of rooms, 6..30 (default: drawn from the seed)");
  g->add_option("--area", gen.area, "minimum floor area, m^2 (never below 300)");
  g->add_flag("--no-objects", gen.no_objects, "rooms, walls and doors only");
  g->add_option("--out,-o", gen.out, "world JSON to write")->required();
  g->footer("The start pose uses sim.uav.flight_height and the object spacing sim.uav.radius from the config.");
  g->callback([] { runGenerate(gen); });

  static RenderArgs ren;
  auto* r = world->add_subcommand("render", "Draw a world top-down as PNG (rooms, walls, doors, objects)");
  r->fallthrough();
  r->add_option("world", ren.world, "world JSON")->required();
  r->add_option("--out,-o", ren.out, "PNG to write")->required();
  r->add_option("--px-per-m", ren.px_per_m, "scale, pixels per metre (labels legible from ~25)")
      ->capture_default_str()
      ->check(CLI::Range(2.0, 200.0));
  r->add_flag("--no-labels", ren.no_labels, "no object labels (room labels stay)");
  r->callback([] { runRender(ren); });

  static StatsArgs st;
  auto* s = world->add_subcommand("stats", "Rooms, objects, floor area and free volume of a world");
  s->fallthrough();
  s->add_option("world", st.world, "world JSON")->required();
  s->add_flag("--json", st.json, "one JSON object on stdout");
  s->footer("floor area = sum of room polygon areas; free volume = sum of room area x height minus the\n"
            "volume of the objects inside rooms (docs/world-format.md).");
  s->callback([] { runStats(st); });

  auto* c = world->add_subcommand("categories", "Print the object table (categories, sizes, rooms) as Markdown");
  c->fallthrough();
  c->callback([] { std::cout << objectTableMarkdown(); });
}

}  // namespace
USSNAV_COMMAND(20, addWorldCommands);
}  // namespace ussnav::cli
