#include "command.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <string>
#include <system_error>

#include "about_text.hpp"
#include "command_line.hpp"
#include "impasto/files/memory_budget.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto_version.hpp"
#include "pigment_folder_option.hpp"
#include "vocabulary.hpp"

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

CLI::App* command_group(CLI::App& root, const std::string& name, const std::string& description) {
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name() == name) return sub;
  }
  CLI::App* group = root.add_subcommand(name, description);
  // `impasto bench` alone lists what it could do rather than failing.
  group->require_subcommand(0, 1);
  group->callback([group] {
    if (group->get_subcommands().empty()) std::cout << help_of(*group);
  });
  return group;
}

CLI::App* bench_group(CLI::App& root) {
  return command_group(root, "bench", "Measure accuracy and speed");
}

void add_registered_commands(CLI::App& root) {
  for (auto& [name, setup] : registry()) setup(root);
}

std::string command_path(const CLI::App& app) {
  if (!app.get_parent()) return "impasto";  // not argv[0], which may be a whole path
  return command_path(*app.get_parent()) + " " + app.get_name();
}

std::string help_of(const CLI::App& app) {
  return app.get_formatter()->make_help(&app, command_path(app), CLI::AppFormatMode::Normal);
}

namespace {

// A command line that does not parse: the error, then how the command is used and where its
// options are listed (CLI11's default says only "Run with --help").
std::string failure_message(const CLI::App* root, const CLI::Error& e) {
  const CLI::App* command = root;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  std::string text = std::string("impasto: ") + e.what() + "\n";
  if (command != root) {
    const std::string path = command_path(*command);
    text += CLI::Formatter().make_usage(command, path);
    text += "`" + path + " --help` lists its options.\n";
  } else {
    text += "`impasto --help` lists the commands.\n";
  }
  return text;
}

}  // namespace

void run_command_in_process(const std::string& command_line) {
  CLI::App root{"impasto"};
  add_registered_commands(root);
  try {
    root.parse(command_line, false);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
}

int run_command_line(int argc, char** argv) {
  CLI::App root{"Impasto: interactive 2.5D painting with thick, spectrally rendered paint"};
  root.require_subcommand(0, 1);
  root.set_version_flag("--version", std::string("impasto " IMPASTO_VERSION "\n") + kLicenceText);
  root.failure_message(failure_message);
  root.footer(
      "Options mean the same in every command (-o/--out the output file, --save the painting, "
      "--size WxH, --wavelengths 1..16|full, --json, --quiet): impasto help vocabulary, "
      "docs/cli.md.");
  add_registered_commands(root);
  setup_pigment_library(root);
  add_quiet_option(root);
  // Plain `impasto` opens the painting window where there is a display to show it on.
  const bool has_display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY");
  const bool has_window =
      !root.get_subcommands([](CLI::App* sub) { return sub->get_name() == "paint"; }).empty();
  try {
    if (argc == 1 && has_display && has_window) {
      root.parse(std::string("paint"), false);
    } else {
      root.parse(argc, argv);
    }
  } catch (const CLI::ParseError& e) {
    return root.exit(e);
  } catch (const std::bad_alloc&) {
    // Loaders and renderers name what they allocate; this is what escaped them.
    const files::MemoryBudget budget = files::memory_budget();
    std::cerr << "impasto: out of memory (an allocation was refused; files are checked against "
                 "a budget of "
              << files::describe_bytes(budget.bytes) << ", set by " << budget.source
              << "; IMPASTO_MEMORY_BUDGET_MB sets it)\n";
    return 1;
  } catch (const std::system_error& e) {
    // The system refused a thread or a mapping: say which limits were in force, not errno alone.
    const files::MemoryBudget budget = files::memory_budget();
    std::cerr << "impasto: the system refused a resource (" << e.what()
              << "): threads or memory beyond this process's limits (the memory left: "
              << files::describe_bytes(budget.bytes) << ", set by " << budget.source
              << "; `ulimit -v` and `ulimit -u` show the limits, --threads 1 needs fewer)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "impasto: " << files::terminal_text(e.what(), true) << "\n";
    return 1;
  }
  if (root.get_subcommands().empty()) {
    std::cout << root.help();
  }
  return 0;
}

}  // namespace impasto::app
