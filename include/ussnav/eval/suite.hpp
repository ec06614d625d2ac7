#pragma once
// Evaluation suites (ussnav eval; format in docs/eval.md): a YAML file listing worlds (generated
// with a style and seed, world JSON files, or datasets to import), goal categories and seeds.
// Episodes are worlds x goals x seeds; a goal the world holds no instance of is skipped (and
// reported), so one goal list serves buildings of different kinds. Paths in the file are
// relative to the file's folder.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

struct SuiteWorld {
  enum class Kind { Generate, File, Import };
  Kind kind = Kind::Generate;
  std::string name;                 // unique in the suite; default: style-seed or file stem
  GeneratorParams generate;         // Kind::Generate
  std::filesystem::path path;       // Kind::File (world JSON) / Kind::Import (dataset file)
  std::vector<std::string> goals;   // overrides the suite's goals when not empty
  std::optional<Pose> start;        // overrides the world's start pose
};

struct Suite {
  std::string name;
  std::vector<SuiteWorld> worlds;
  std::vector<std::string> goals;
  std::vector<uint64_t> seeds{1};
  std::optional<double> max_time_s; // overrides episode.max_time_s
};

// Throws InputError(file, dotted field, what was expected) on a malformed suite.
Suite loadSuite(const std::filesystem::path& path);

// Builds (generates, loads or imports) the world. Throws InputError on bad data.
World materializeWorld(const SuiteWorld& w);

struct SuiteEpisode {
  size_t world = 0;                 // index into Suite::worlds
  std::string goal;
  uint64_t seed = 1;
};

}  // namespace ussnav
