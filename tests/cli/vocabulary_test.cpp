// The command line's vocabulary (app/src/vocabulary.hpp): docs/cli.md lists it as the
// program does, a shared option means the same in every command, and each choice's names
// are the ones its parser takes.
#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "command.hpp"
#include "impasto/cracks/cavity.hpp"
#include "impasto/paintcore/paint_body.hpp"
#include "impasto/render/render_settings.hpp"
#include "pigment_folder_option.hpp"
#include "vocabulary.hpp"

namespace impasto::app {
namespace {

std::string docs_section() {
  std::ifstream in(std::string(IMPASTO_SOURCE_DIR) + "/docs/cli.md");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- impasto help vocabulary: begin -->\n";
  const std::string end = "<!-- impasto help vocabulary: end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  if (a == std::string::npos || b == std::string::npos || b < a) return "(no markers)";
  return doc.substr(a + begin.size(), b - a - begin.size());
}

TEST(CommandLineDocs, ListTheProgramsVocabulary) {
  // On a difference: build/release/app/impasto help vocabulary, pasted between the markers.
  EXPECT_EQ(docs_section(), vocabulary_markdown());
}

// Every option of every command, with the command's path ("bench sim").
void for_each_option(CLI::App& app, const std::string& path,
                     const std::function<void(const std::string&, const CLI::Option&)>& visit) {
  for (const CLI::Option* option : app.get_options()) visit(path, *option);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for_each_option(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), visit);
}

TEST(CommandLineVocabulary, ASharedOptionMeansTheSameInEveryCommand) {
  CLI::App root{"impasto"};
  add_registered_commands(root);
  setup_pigment_library(root);
  add_quiet_option(root);
  std::map<std::string, const VocabularyWord*> words;  // by long name
  for (const VocabularyWord& word : vocabulary()) {
    const std::string names(word.names);
    words[names.substr(names.rfind(',') + 1)] = &word;
  }
  // Commands written at the same time as the vocabulary, not yet on its shared options (their
  // --size, --out, --save, --wavelengths, --threads and --json mean the same, in other words).
  // Move each onto the add_*_option helpers and take it off this list.
  // bench surface's --size is one number, cells each way.
  const std::set<std::string> not_yet{"edit", "export", "bench render", "bench surface"};
  int checked = 0;
  for_each_option(root, "", [&](const std::string& path, const CLI::Option& option) {
    if (option.get_group().empty()) return;  // an old spelling, hidden
    if (not_yet.count(path)) return;
    for (const std::string& name : option.get_lnames()) {
      const auto word = words.find("--" + name);
      if (word == words.end()) continue;
      ++checked;
      EXPECT_EQ(option.get_description().rfind(std::string(word->second->meaning), 0), 0u)
          << path << " --" << name << ": '" << option.get_description() << "'";
      EXPECT_EQ(option.get_name(false, true), std::string(word->second->names))
          << path << " --" << name;
    }
  });
  EXPECT_GT(checked, 40);  // --pigments and --quiet alone are on every command
}

TEST(CommandLineVocabulary, EachChoiceNameIsOneItsParserTakes) {
  const std::map<std::string, std::function<void(const std::string&)>> parsers{
      {"--light-type", [](const std::string& n) { render::parse_light_type(n); }},
      {"--display", [](const std::string& n) { render::parse_display_encoding(n); }},
      {"--adaptation", [](const std::string& n) { render::parse_chromatic_adaptation(n); }},
      {"--weights", [](const std::string& n) { render::parse_node_weights(n); }},
      {"--storage", [](const std::string& n) { render::parse_reflectance_storage(n); }},
      {"--crack-model", [](const std::string& n) { render::parse_crack_model(n); }},
      {"--shape", [](const std::string& n) { cracks::shape_from_name(n); }},
      {"--flake-depth",
       [](const std::string& n) { util::parse_name(render::kFlakeDepthNames, n, "flake depth"); }},
      {"--surface",
       [](const std::string& n) { util::parse_name(render::kSurfaceModelNames, n, "surface"); }},
      {"--medium",
       [](const std::string& n) { util::parse_name(render::surface::kFinishNames, n, "medium"); }},
      {"--varnish",
       [](const std::string& n) {
         if (n != "none") util::parse_name(render::surface::kFinishNames, n, "varnish");
       }},
      {"--body",
       [](const std::string& n) {
         if (!paintcore::paint_body_from_name(n)) throw std::runtime_error("unknown body " + n);
       }},
  };
  ASSERT_EQ(vocabulary_choices().size(), parsers.size());
  for (const VocabularyChoice& choice : vocabulary_choices()) {
    const auto parse = parsers.find(choice.option);
    ASSERT_NE(parse, parsers.end()) << choice.option;
    for (const std::string& name : choice.names) EXPECT_NO_THROW(parse->second(name)) << name;
    EXPECT_NO_THROW(parse->second(choice.default_name)) << choice.option;
    EXPECT_THROW(parse->second("no-such-" + choice.option.substr(2)), std::runtime_error);
  }
}

TEST(CommandLineVocabulary, SizesAndWavelengthsParseAsDocumented) {
  EXPECT_EQ(parse_canvas_size("1024x768").width, 1024);
  EXPECT_EQ(parse_canvas_size("1024x768").height, 768);
  for (const char* bad : {"1024", "1024x", "x768", "0x5", "5x-1", "12x12junk", "200000x5"})
    EXPECT_THROW(parse_canvas_size(bad), std::runtime_error) << bad;
  EXPECT_EQ(parse_wavelengths("1"), 1);
  EXPECT_EQ(parse_wavelengths("16"), 16);
  EXPECT_EQ(parse_wavelengths("full"), 0);
  for (const char* bad : {"17", "-1", "", "8.5", "all"})
    EXPECT_THROW(parse_wavelengths(bad), std::runtime_error) << bad;
  EXPECT_THROW(parse_wavelengths("full", false), std::runtime_error);
  EXPECT_THROW(parse_wavelengths("0", false), std::runtime_error);
}

}  // namespace
}  // namespace impasto::app
