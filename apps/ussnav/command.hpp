#pragma once
// Subcommand registry for the `ussnav` CLI. Each apps/ussnav/cmd_*.cpp file registers its own
// subcommands with USSNAV_COMMAND(order, fn); main() builds the CLI11 app from the registry.
// Shared options (--config, --set) live on the root app and fall through to subcommands.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "ussnav/core/config.hpp"

namespace ussnav::cli {

// Options common to every command.
struct Globals {
  std::string config_path;               // --config; empty = configs/default.yaml or defaults
  std::vector<std::string> overrides;    // --set key=value (repeatable)
  bool quiet = false;                    // --quiet: no progress lines
  // Loads the config once (file + overrides); throws InputError on bad input.
  const Config& config();

 private:
  bool loaded_ = false;
  Config cfg_;
};

Globals& globals();

using CommandFactory = std::function<void(CLI::App& root)>;
bool registerCommand(int order, CommandFactory f);
std::vector<std::pair<int, CommandFactory>>& commandRegistry();

// The subcommand `name` of `parent`, created (with `description`, fallthrough on) if absent.
// Lets several cmd_*.cpp files add children to one group, e.g. `world generate|import`.
CLI::App* subcommandGroup(CLI::App& parent, const std::string& name, const std::string& description);

// Progress line on stderr (overwritten in place when stderr is a terminal).
void progress(const std::string& line);
void progressDone();

}  // namespace ussnav::cli

#define USSNAV_CONCAT2(a, b) a##b
#define USSNAV_CONCAT(a, b) USSNAV_CONCAT2(a, b)
#define USSNAV_COMMAND(order, fn) \
  static const bool USSNAV_CONCAT(ussnav_cmd_reg_, __LINE__) = ::ussnav::cli::registerCommand(order, fn)
