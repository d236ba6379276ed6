// impasto help [vocabulary | params]: the top-level help, the options every command shares and
// the names of each choice (the reference docs/cli.md holds), or the paint model's constants
// (docs/simulation.md holds them); tests compare both.
#include <iostream>
#include <memory>

#include "command.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::help_cmd {
namespace {

const CommandRegistrar registrar("help", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand("help", "This help, or the options shared by every command");
  cmd->require_subcommand(0, 1);
  CLI::App* words = cmd->add_subcommand(
      "vocabulary", "The options shared by every command and each choice's names (Markdown)");
  words->callback([] { std::cout << vocabulary_markdown(); });
  CLI::App* params = cmd->add_subcommand(
      "params", "The paint model's constants (--param NAME=VALUE): defaults, ranges (Markdown)");
  params->callback([] { std::cout << params_markdown(); });
  cmd->callback([cmd, &root] {
    // root.help() would show the selected command's (this one's) help.
    if (cmd->get_subcommands().empty())
      std::cout << root.get_formatter()->make_help(&root, root.get_name(),
                                                   CLI::AppFormatMode::Normal);
  });
});

}  // namespace
}  // namespace impasto::app::help_cmd
