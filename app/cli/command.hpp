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

// The sub-command group NAME of root (e.g. "bench"), created on first use, so that several
// files can add sub-commands to it ("bench sim", "bench color").
CLI::App* command_group(CLI::App& root, const std::string& name, const std::string& description);
// The group "bench" (its description written once here), which each `impasto bench ...`
// command's file adds its sub-command to.
CLI::App* bench_group(CLI::App& root);

// "impasto bench sim": the command's names from the top.
std::string command_path(const CLI::App& app);
// The command's --help text.
std::string help_of(const CLI::App& app);

// Every registered command, sorted by name, added to root.
void add_registered_commands(CLI::App& root);

}  // namespace impasto::app
