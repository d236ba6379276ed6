#include "command.hpp"

#include <map>

namespace impasto::app {
namespace {
std::map<std::string, CommandSetup>& registry() {
  static std::map<std::string, CommandSetup> commands;
  return commands;
}
}  // namespace

CommandRegistrar::CommandRegistrar(std::string name, CommandSetup setup) {
  registry().emplace(std::move(name), std::move(setup));
}

CLI::App* command_group(CLI::App& root, const std::string& name,
                        const std::string& description) {
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name() == name) return sub;
  }
  CLI::App* group = root.add_subcommand(name, description);
  group->require_subcommand(1);
  return group;
}

void add_registered_commands(CLI::App& root) {
  for (auto& [name, setup] : registry()) setup(root);
}

}  // namespace impasto::app
