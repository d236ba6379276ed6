#pragma once
// Sub-commands of the impasto executable register themselves here, one file each, so that
// main.cpp never changes when a command is added.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace impasto::app {

// Adds one sub-command (with its options and callback) to the top-level CLI::App.
using CommandSetup = std::function<void(CLI::App& root)>;

// Called from a static object in each command's .cpp file.
struct CommandRegistrar {
  CommandRegistrar(std::string name, CommandSetup setup);
};

// Every registered command, sorted by name, added to root.
void add_registered_commands(CLI::App& root);

}  // namespace impasto::app
