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

void add_registered_commands(CLI::App& root) {
  for (auto& [name, setup] : registry()) setup(root);
}

}  // namespace impasto::app
