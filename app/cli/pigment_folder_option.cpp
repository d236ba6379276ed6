#include "pigment_folder_option.hpp"

#include <impasto/data/pigment_library.hpp>
#include <impasto/render/pigment_records.hpp>

#include <filesystem>
#include <string>

#include "vocabulary.hpp"

namespace impasto::app {
namespace {

void add_to(CLI::App& app) {
  if (app.get_option_no_throw("--pigments") == nullptr) {
    app.add_option_function<std::string>(
           "--pigments", [](const std::string& folder) { data::add_pigment_folder(folder); },
           vocabulary_help("--pigments"))
        ->check(CLI::ExistingDirectory)
        ->trigger_on_parse();  // each time it is given, before any command runs
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) add_to(*sub);
}

}  // namespace

void setup_pigment_library(CLI::App& root) {
  add_to(root);
  render::install_pigment_records();
}

}  // namespace impasto::app
