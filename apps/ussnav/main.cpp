// `ussnav`: the command-line front end. Subcommands register themselves (command.hpp); this
// file parses, dispatches, and turns errors into one clear line and a non-zero exit.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "ussnav/core/error.hpp"

namespace ussnav::cli {

Globals& globals() {
  static Globals g;
  return g;
}

const Config& Globals::config() {
  if (!loaded_) {
    std::filesystem::path p = config_path.empty() ? defaultConfigPath() : std::filesystem::path(config_path);
    cfg_ = p.empty() ? defaultConfig(overrides) : loadConfig(p, overrides);
    loaded_ = true;
  }
  return cfg_;
}

std::vector<std::pair<int, CommandFactory>>& commandRegistry() {
  static std::vector<std::pair<int, CommandFactory>> r;
  return r;
}

bool registerCommand(int order, CommandFactory f) {
  commandRegistry().emplace_back(order, std::move(f));
  return true;
}

CLI::App* subcommandGroup(CLI::App& parent, const std::string& name, const std::string& description) {
  for (CLI::App* existing : parent.get_subcommands({}))
    if (existing->get_name() == name) return existing;
  CLI::App* g = parent.add_subcommand(name, description);
  g->require_subcommand(1);
  g->fallthrough();
  return g;
}

namespace {
// Without a terminal (CI logs, files) progress lines are rate-limited to one per 5 s; the last
// one is always printed by progressDone().
std::string g_pending;
std::chrono::steady_clock::time_point g_last_print{};
}  // namespace

void progress(const std::string& line) {
  if (globals().quiet) return;
  static const bool tty = ::isatty(2);
  if (tty) {
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
  } else {
    const auto now = std::chrono::steady_clock::now();
    if (now - g_last_print < std::chrono::seconds(5)) {
      g_pending = line;
      return;
    }
    g_last_print = now;
    g_pending.clear();
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

void progressDone() {
  static const bool tty = ::isatty(2);
  if (globals().quiet) return;
  if (tty) {
    std::fprintf(stderr, "\n");
  } else if (!g_pending.empty()) {
    std::fprintf(stderr, "%s\n", g_pending.c_str());
    g_pending.clear();
  }
  g_last_print = {};
}

}  // namespace ussnav::cli

int main(int argc, char** argv) {
  using namespace ussnav::cli;
  CLI::App app{"ussnav: zero-shot object navigation on a Unified Spatio-Semantic Scene Graph"};
  app.set_version_flag("--version", std::string("ussnav ") + USSNAV_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  auto& g = globals();
  app.add_option("--config", g.config_path, "YAML config (default: configs/default.yaml)")
      ->check(CLI::ExistingFile);
  app.add_option("--set", g.overrides, "override a config value, e.g. --set skeleton.max_radius=1.2")
      ->allow_extra_args(false);
  app.add_flag("--quiet,-q", g.quiet, "no progress lines");

  auto& reg = commandRegistry();
  std::stable_sort(reg.begin(), reg.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (auto& [order, f] : reg) f(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad command line (a missing file, an unknown option, a
    // value out of range) is bad input like any other: exit 2 (CLI11's own codes are 100+).
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const ussnav::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
