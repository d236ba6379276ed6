#pragma once
// The command line's shared words as data (vocabulary.hpp adds them to commands): what each
// shared option means, the choices of each option over an enum, and the parsers of the
// values several commands take. Free of CLI11, so that what only reads them (the
// vocabulary's test) does not compile it.
#include <string>
#include <string_view>
#include <vector>

namespace impasto::render {
struct RenderSettings;
}

namespace impasto::app {

// One shared option: its names, its argument and what it means wherever it appears.
struct VocabularyWord {
  std::string_view names;     // "-o,--out"
  std::string_view argument;  // "FILE"
  std::string_view meaning;   // the start of its help text in every command
  std::string_view details;   // for the reference only: what follows from the meaning
};
const std::vector<VocabularyWord>& vocabulary();

// One option with a fixed set of choices, read from its enum's table.
struct VocabularyChoice {
  std::string option;              // "--light-type"
  std::string what;                // "the main light's kind"
  std::vector<std::string> names;  // in the table's order
  std::string default_name;
};
const std::vector<VocabularyChoice>& vocabulary_choices();

// The help text of the shared option `names` ("-o,--out"): its meaning, then ": detail".
std::string vocabulary_help(std::string_view names, std::string_view detail = {});

// The Markdown reference: both tables (what `impasto help vocabulary` prints).
std::string vocabulary_markdown();
// The paint model's constants (`--param NAME=VALUE`) from their one table
// (paintcore::all_simulation_params): name, default, range and meaning, as Markdown
// (`impasto help params`; docs/simulation.md holds it and a test compares).
std::string params_markdown();

// "impasto: warning: TEXT" on stderr (also under --quiet: a warning is never noise).
void warn(const std::string& text);
// A line for the user on stdout, unless --quiet.
void note(const std::string& text);

// A canvas size in cells.
struct CanvasSize {
  int width = 0, height = 0;
};
// "WIDTHxHEIGHT" (1..131072 each); throws std::runtime_error naming `option` and the text.
CanvasSize parse_canvas_size(const std::string& text, std::string_view option = "--size");
// --light-dir's "AZIMUTH,ELEVATION" in degrees into the settings; throws naming the option.
void parse_light_direction(const std::string& text, render::RenderSettings& settings);
// "1".."16" or "full" (0: every nm); throws std::runtime_error naming the text.
int parse_wavelengths(const std::string& text, bool full_allowed = true);

}  // namespace impasto::app
