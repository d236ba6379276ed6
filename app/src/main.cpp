// impasto: paint with thick, spectrally rendered paint.
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <exception>
#include <iostream>

#include "command.hpp"

int main(int argc, char** argv) {
  CLI::App root{"Impasto: interactive 2.5D painting with thick, spectrally rendered paint"};
  root.require_subcommand(0, 1);
  root.set_version_flag("--version", "impasto 0.1.0");
  impasto::app::add_registered_commands(root);
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
  } catch (const std::exception& e) {
    std::cerr << "impasto: " << e.what() << "\n";
    return 1;
  }
  if (root.get_subcommands().empty()) {
    std::cout << root.help();
  }
  return 0;
}
