#include "command_catalogue.hpp"

#include <CLI/CLI.hpp>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "command.hpp"
#include "pigment_folder_option.hpp"
#include "vocabulary.hpp"

namespace impasto::app {
namespace {

// The command tree with the options every command shares (run_command_line's).
void build_commands(CLI::App& root) {
  add_registered_commands(root);
  setup_pigment_library(root);
  add_quiet_option(root);
}

void for_each_command(CLI::App& app, const std::string& path,
                      const std::function<void(CLI::App&, const std::string&)>& visit) {
  visit(app, path);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for_each_command(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), visit);
}

}  // namespace

std::vector<std::string> command_paths() {
  CLI::App root{"impasto"};
  build_commands(root);
  std::vector<std::string> paths;
  for_each_command(root, "", [&](CLI::App&, const std::string& path) {
    if (!path.empty()) paths.push_back(path);
  });
  return paths;
}

std::string command_help(const std::string& path) {
  CLI::App root{"impasto"};
  build_commands(root);
  CLI::App* app = &root;
  std::istringstream names(path);
  for (std::string name; names >> name;) app = app->get_subcommand(name);  // throws if none
  return help_of(*app);
}

std::vector<CommandOption> command_options() {
  CLI::App root{"impasto"};
  build_commands(root);
  std::vector<CommandOption> options;
  for_each_command(root, "", [&](CLI::App& app, const std::string& path) {
    for (const CLI::Option* option : app.get_options())
      options.push_back({path, option->get_lnames(), option->get_snames(), option->get_group(),
                         option->get_description()});
  });
  return options;
}

}  // namespace impasto::app
