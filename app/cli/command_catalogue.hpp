#pragma once
// The program's commands and their options as plain data, for what walks them (the tests of
// the command line and of its vocabulary): built from the registered commands, as main()
// builds them, and compiled with the commands, so that a reader does not compile CLI11.
#include <string>
#include <vector>

namespace impasto::app {

// Every sub-command's path below the program ("render", "bench", "bench sim").
std::vector<std::string> command_paths();

// The --help text of the command at `path` ("" for the program itself).
std::string command_help(const std::string& path);

// One option of one command.
struct CommandOption {
  std::string command;                   // its command's path ("" for the program)
  std::vector<std::string> long_names;   // without "--"
  std::vector<std::string> short_names;  // without "-"
  std::string group;                     // empty: an old spelling, hidden from the help
  std::string description;
};
// Every option of every command, the program's own included.
std::vector<CommandOption> command_options();

}  // namespace impasto::app
