// The command line's vocabulary (app/cli/vocabulary.hpp): docs/cli.md lists it as the
// program does, a shared option means the same in every command, and each choice's names
// are the ones its parser takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "command_catalogue.hpp"
#include "impasto/cracks/cavity.hpp"
#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/simulation_params.hpp"
#include "impasto/paintcore/step_quality.hpp"
#include "impasto/render/render_settings.hpp"
#include "vocabulary_words.hpp"

namespace impasto::app {
namespace {

// The text between `<!-- impasto help WHAT: begin -->` and its end marker in a doc.
std::string docs_section(const std::string& doc_name = "cli.md",
                         const std::string& what = "vocabulary") {
  std::ifstream in(std::string(IMPASTO_SOURCE_DIR) + "/docs/" + doc_name);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- impasto help " + what + ": begin -->\n";
  const std::string end = "<!-- impasto help " + what + ": end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  if (a == std::string::npos || b == std::string::npos || b < a) return "(no markers)";
  return doc.substr(a + begin.size(), b - a - begin.size());
}

TEST(CommandLineDocs, ListTheProgramsVocabulary) {
  // On a difference: build/release/app/impasto help vocabulary, pasted between the markers.
  EXPECT_EQ(docs_section(), vocabulary_markdown());
}

TEST(CommandLineDocs, ListThePaintModelsConstantsFromTheirOneTable) {
  // On a difference: build/release/app/impasto help params, pasted between the markers.
  EXPECT_EQ(docs_section("simulation.md", "params"), params_markdown());
  // Each row's default is inside its range (the table and SimulationParams agree).
  EXPECT_NO_THROW(paintcore::validate(paintcore::SimulationParams{}));
}

// What a shared option's help must say, in any words, wherever it appears: the mark of its
// one meaning (a --size that takes one number, or an --out that writes a painting, fails).
struct Meaning {
  std::vector<std::string> says_one_of;
  std::string never_says;
};
const std::map<std::string, Meaning>& shared_meanings() {
  static const std::map<std::string, Meaning> meanings{
      {"--size", {{"WxH", "WIDTHxHEIGHT"}, ""}},
      {"--dpi", {{"per inch"}, ""}},
      {"--wavelengths", {{"16"}, ""}},
      {"--out", {{""}, ".impasto"}},
      {"--save", {{".impasto", "painting"}, ""}},
      {"--json", {{"JSON"}, ""}},
      {"--threads", {{"0: all cores"}, ""}},
      {"--light", {{"D65"}, ""}},
      {"--param", {{"constant"}, ""}},
      {"--pigments", {{"Pigment folder"}, ""}},
      {"--quiet", {{"progress"}, ""}},
  };
  return meanings;
}

TEST(CommandLineVocabulary, EveryWordHasItsMark) {
  for (const VocabularyWord& word : vocabulary()) {
    const std::string names(word.names);
    const auto meaning = shared_meanings().find(names.substr(names.rfind(',') + 1));
    ASSERT_NE(meaning, shared_meanings().end()) << names;
    const std::string help = vocabulary_help(word.names);
    bool says = false;
    for (const std::string& mark : meaning->second.says_one_of)
      says |= help.find(mark) != std::string::npos;
    EXPECT_TRUE(says) << names << ": " << help;
  }
  EXPECT_EQ(vocabulary().size(), shared_meanings().size());
}

TEST(CommandLineVocabulary, ASharedOptionMeansTheSameInEveryCommand) {
  int checked = 0;
  for (const CommandOption& option : command_options()) {
    const std::string& path = option.command;
    if (option.group.empty()) continue;  // an old spelling, hidden
    for (const std::string& name : option.long_names) {
      const auto meaning = shared_meanings().find("--" + name);
      if (meaning == shared_meanings().end()) continue;
      ++checked;
      const std::string& help = option.description;
      bool says = false;
      for (const std::string& mark : meaning->second.says_one_of)
        says |= help.find(mark) != std::string::npos;
      EXPECT_TRUE(says) << path << " --" << name << ": '" << help << "'";
      if (!meaning->second.never_says.empty()) {
        EXPECT_EQ(help.find(meaning->second.never_says), std::string::npos)
            << path << " --" << name << ": '" << help << "'";
      }
    }
    for (const std::string& name : option.short_names)
      if (name == "o") {
        EXPECT_NE(std::find(option.long_names.begin(), option.long_names.end(), "out"),
                  option.long_names.end())
            << path << " -o";
      }
  }
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
      {"--quality",
       [](const std::string& n) { util::parse_name(paintcore::kStepQualityNames, n, "quality"); }},
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
