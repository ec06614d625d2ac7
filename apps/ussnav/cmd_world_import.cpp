// `ussnav world import <file> --out W.json`: turn third-party building data (ProcTHOR house,
// Webots apartment, OctoMap/PCD scan) into a world file, with a one-line summary.

#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav::cli {
namespace {

struct ImportArgs {
  std::string input;
  std::string out;
  std::string assets;
  double resolution = 0.0;
  double flight_height = 1.2;
};

void runImport(const ImportArgs& a) {
  ImportOptions opt;
  opt.asset_database = a.assets;
  opt.scan_resolution = a.resolution;
  opt.flight_height = a.flight_height;
  ImportReport rep;
  Stopwatch sw;
  progress("importing " + a.input + " ...");
  World w = importWorld(a.input, opt, &rep);
  const double secs = sw.ms() / 1000.0;
  saveWorld(w, a.out);
  progressDone();
  if (!globals().quiet) {
    for (const auto& n : rep.notes) std::cerr << "note: " << n << "\n";
    const size_t shown = std::min<size_t>(rep.warnings.size(), 10);
    for (size_t i = 0; i < shown; ++i) std::cerr << "warning: " << rep.warnings[i] << "\n";
    if (rep.warnings.size() > shown) std::cerr << "warning: ... and " << rep.warnings.size() - shown << " more\n";
  }
  const Vec3 size = w.bounds().size();
  char line[512];
  std::snprintf(line, sizeof line,
                "imported %s '%s': %zu rooms, %zu doors, %zu objects (%d dropped outside rooms), %zu obstacle "
                "voxels, bounds %.1f x %.1f x %.1f m, %.2f s -> %s",
                rep.format.c_str(), w.name.c_str(), w.rooms.size(), w.doors.size(), w.objects.size(),
                rep.dropped_objects, w.obstacles.cells.size(), size.x(), size.y(), size.z(), secs, a.out.c_str());
  std::cout << line << "\n";
}

void addWorldImport(CLI::App& root) {
  auto* world = subcommandGroup(root, "world", "Create, import, inspect and draw worlds");
  auto args = std::make_shared<ImportArgs>();
  auto* cmd = world->add_subcommand("import", "Convert third-party building data into a world file");
  cmd->fallthrough();
  cmd->footer("Accepted: " + acceptedImportFormats());
  cmd->add_option("file", args->input, "ProcTHOR house .json, Webots apartment folder/.wbt/rooms_enu.tsv, "
                                      "AWS Gazebo world folder/.world/objects.tsv, .bt/.ot octree or .pcd point cloud")
      ->required();
  cmd->add_option("--out,-o", args->out, "world JSON to write (atomically)")->required();
  cmd->add_option("--assets", args->assets, "ProcTHOR asset sizes (asset_bboxes.tsv or asset-database.json); "
                                            "default: beside the house folder");
  cmd->add_option("--resolution", args->resolution, "voxel size in m of scans and Gazebo wall meshes (default: the octree's own; 0.1 for .pcd and Gazebo)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--flight-height", args->flight_height, "start pose height above the floor, m")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] { runImport(*args); });
}

}  // namespace
USSNAV_COMMAND(21, addWorldImport);
}  // namespace ussnav::cli
