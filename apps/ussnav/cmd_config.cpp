// `ussnav config print|check`: show the effective configuration, or validate a file.

#include <iostream>

#include "command.hpp"

namespace ussnav::cli {
namespace {

void addConfigCommands(CLI::App& root) {
  auto* cmd = subcommandGroup(root, "config", "Print or check the configuration");
  auto* print = cmd->add_subcommand("print", "Print the effective config (file + --set) as YAML");
  print->fallthrough();
  print->callback([] { std::cout << configToYaml(globals().config()); });
  auto* check = cmd->add_subcommand("check", "Validate the config; exit 2 with the bad key if invalid");
  check->fallthrough();
  check->callback([] {
    globals().config();
    std::cout << "config ok\n";
  });
}

}  // namespace
USSNAV_COMMAND(90, addConfigCommands);
}  // namespace ussnav::cli
