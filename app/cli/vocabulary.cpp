#include "vocabulary.hpp"

#include <impasto/paintcore/step_quality.hpp>

#include <impasto/cracks/cavity.hpp>
#include <impasto/paintcore/paint_body.hpp>
#include <impasto/paintcore/simulation_params.hpp>
#include <impasto/render/render_settings.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"
#include "progress_reporter.hpp"

namespace impasto::app {
namespace {

// A CLI11 check that runs `parse` on the text (which may rewrite it) and reports its error.
CLI::Validator parsing_check(std::string description,
                             std::function<std::string(const std::string&)> parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          text = parse(text);
        } catch (const std::exception& e) {
          // CLI11 puts the option's name before the message: drop the parser's own.
          std::string message = e.what();
          if (message.starts_with("--") && message.find(": ") != std::string::npos)
            message.erase(0, message.find(": ") + 2);
          return message;
        }
        return {};
      },
      std::move(description));
}

template <typename Enum, std::size_t N>
VocabularyChoice choice(std::string option, std::string what, const util::EnumNames<Enum, N>& names,
                        Enum default_value) {
  return {std::move(option), std::move(what), util::names_of(names),
          std::string(util::name_of(names, default_value))};
}

// A Markdown table cell's text: '|' escaped, even inside backticks (GitHub's tables).
std::string table_cell(std::string_view text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c);
  return cell;
}

}  // namespace

const std::vector<VocabularyWord>& vocabulary() {
  static const std::vector<VocabularyWord> words{
      {"--size", "WxH", "Canvas size in cells, WIDTHxHEIGHT",
       "a new canvas, or one that overrides a recording's"},
      {"--dpi", "DPI", "Canvas resolution in cells per inch", ""},
      {"--wavelengths", "1..16|full",
       "Wavelengths of the spectral colour: 1..16 Gaussian nodes, or full (every nm)",
       "full only where the CPU renders; the window and --gpu take 1..16"},
      {"-o,--out", "FILE", "Output file",
       "the image where a command renders one (FILE.png, FILE.exr), else its CSV, plot or "
       "recording; never a painting (that is --save)"},
      {"--save", "FILE.impasto", "Save the painting here",
       "only ever a painting; an old `replay --out X.impasto` still saves, with a warning"},
      {"--json", "", "Print the results as JSON",
       "for scripts: one object, or one object a line for tables; nothing else on standard "
       "output"},
      {"--threads", "N", "Worker threads (0: all cores)", "results do not depend on it"},
      {"--light", "SPEC", "Light: D65, A, F11, ..., blackbody:KELVIN or a spectral CSV", ""},
      {"--param", "NAME=VALUE", "Set a paint model constant; repeatable",
       "the constants, their defaults and ranges: `impasto help params`, docs/simulation.md"},
      {"--pigments", "DIR",
       "Pigment folder layered over the bundled and user pigments (docs/pigments.md)",
       "on every command; repeatable, later folders win"},
      {"-q,--quiet", "", "No progress and no notes: only results, warnings and errors",
       "on every command"},
  };
  return words;
}

const std::vector<VocabularyChoice>& vocabulary_choices() {
  static const std::vector<VocabularyChoice> choices = [] {
    const render::RenderSettings defaults;
    std::vector<VocabularyChoice> list{
        choice("--light-type", "the main light's kind", render::kLightTypeNames,
               defaults.light_type),
        choice("--display", "the PNG's encoding", render::kDisplayEncodingNames, defaults.display),
        choice("--adaptation", "chromatic adaptation to the display's white",
               render::kChromaticAdaptationNames, defaults.adaptation),
        choice("--weights", "wavelength nodes and their XYZ weights", render::kNodeWeightsNames,
               defaults.node_weights),
        choice("--storage", "the baked reflectance's precision", render::kReflectanceStorageNames,
               defaults.storage),
        choice("--flake-depth", "the flake sparkles' depth model", render::kFlakeDepthNames,
               defaults.flake_masking),
        choice("--crack-model", "a crack's apparent reflectance", cracks::kCavityModelNames,
               defaults.crack_model),
        choice("--shape", "a crack's or a pit's section", cracks::kCavityShapeNames,
               cracks::CavityShape::VGroove),
    };
    list.push_back(choice("--quality", "how finely the simulation steps a brush",
                          paintcore::kStepQualityNames, paintcore::StepQuality::balanced));
    list.push_back(choice("--surface", "the paint surface's reflection model",
                          render::kSurfaceModelNames, defaults.surface.model));
    list.push_back(choice("--medium", "the finish the paint's medium dries to",
                          render::surface::kFinishNames, defaults.surface.medium));
    VocabularyChoice varnish{"--varnish",
                             "a varnish: render's where the painting has none, edit's a coat",
                             {"none"},
                             "none"};
    for (const std::string& finish : util::names_of(render::surface::kFinishNames))
      varnish.names.push_back(finish);
    list.push_back(std::move(varnish));
    VocabularyChoice bodies{"--body", "a paint's body, fluid to paste", {}, ""};
    for (const auto& info : paintcore::kPaintBodies) bodies.names.emplace_back(info.name);
    bodies.default_name = paintcore::body_info(paintcore::kDefaultPaintBody).name;
    list.push_back(std::move(bodies));
    return list;
  }();
  return choices;
}

std::string vocabulary_markdown() {
  std::string text = "| option | argument | means, in every command that has it |\n|---|---|---|\n";
  for (const VocabularyWord& word : vocabulary()) {
    std::string names;  // "-o,--out" as "`-o`, `--out`"
    for (const char c : word.names) names += c == ',' ? std::string("`, `") : std::string(1, c);
    text += "| `" + names + "` | " +
            (word.argument.empty() ? std::string() : "`" + table_cell(word.argument) + "`") +
            " | " + std::string(word.meaning) +
            (word.details.empty() ? std::string() : "; " + std::string(word.details)) + " |\n";
  }
  text += "\n| option | chooses | names | default |\n|---|---|---|---|\n";
  for (const VocabularyChoice& c : vocabulary_choices()) {
    std::string names;
    for (const std::string& name : c.names) names += (names.empty() ? "`" : ", `") + name + "`";
    text += "| `" + c.option + "` | " + c.what + " | " + names + " | `" + c.default_name + "` |\n";
  }
  return text;
}

void parse_light_direction(const std::string& text, render::RenderSettings& settings) {
  const auto comma = text.find(',');
  try {
    if (comma == std::string::npos) throw std::invalid_argument("no comma");
    std::size_t used_az = 0, used_el = 0;
    const std::string az = text.substr(0, comma);
    const std::string el = text.substr(comma + 1);
    const double azimuth = std::stod(az, &used_az);
    const double elevation = std::stod(el, &used_el);
    if (used_az != az.size() || used_el != el.size() || !std::isfinite(azimuth) ||
        !std::isfinite(elevation))
      throw std::invalid_argument("junk");
    settings.light_azimuth_deg = azimuth;
    settings.light_elevation_deg = elevation;
  } catch (const std::exception&) {
    throw std::runtime_error("--light-dir " + text.substr(0, 32) +
                             ": expected AZIMUTH,ELEVATION in degrees, e.g. 225,60");
  }
}

CLI::Option* add_light_dir_option(CLI::App& cmd, std::string& light_dir) {
  return cmd
      .add_option("--light-dir", light_dir,
                  "Light azimuth,elevation in degrees (azimuth from +x toward +y, down)")
      ->capture_default_str();
}

std::string params_markdown() {
  const auto shown = [](double v) { return util::number_text(v); };
  const paintcore::SimulationParams defaults;
  std::string text = "| field | default | range | meaning |\n|---|---|---|---|\n";
  for (const paintcore::NamedParam& row : paintcore::all_simulation_params()) {
    text += "| " + std::string(row.name) + " | " + shown(defaults.*row.field) + " | " +
            (row.lowest_excluded ? "(" : "[") + shown(row.lowest) + ", " + shown(row.highest) +
            "]" + (*row.unit != '\0' ? std::string(" ") + row.unit : std::string()) + " | " +
            row.meaning + " |\n";
  }
  return text;
}

std::string vocabulary_help(std::string_view names, std::string_view detail) {
  for (const VocabularyWord& word : vocabulary()) {
    if (word.names == names) {
      std::string help(word.meaning);
      if (!detail.empty()) help += ": " + std::string(detail);
      return help;
    }
  }
  throw std::logic_error("no vocabulary word " + std::string(names));
}

void warn(const std::string& text) {
  std::cerr << "impasto: warning: " << files::terminal_text(text, true) << "\n";
}

void note(const std::string& text) {
  if (!quiet()) std::cout << files::terminal_text(text, true) << "\n";
}

CanvasSize parse_canvas_size(const std::string& text, std::string_view option) {
  const auto x = text.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    std::size_t used_w = 0, used_h = 0;
    const int w = std::stoi(text.substr(0, x), &used_w);
    const int h = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("junk");
    if (w < 1 || h < 1 || w > (1 << 17) || h > (1 << 17)) throw std::out_of_range("size");
    return {w, h};
  } catch (const std::logic_error&) {
    throw std::runtime_error(std::string(option) +
                             ": expected WIDTHxHEIGHT in cells (1..131072 each), e.g. 1024x768, "
                             "not '" +
                             text + "'");
  }
}

int parse_wavelengths(const std::string& text, bool full_allowed) {
  if (text == "full" || (text == "0" && full_allowed)) {
    if (!full_allowed)
      throw std::runtime_error(
          "full (every nm) is the CPU render's (impasto render); here 1..16 nodes");
    if (text == "0") warn("--wavelengths 0 is deprecated: use --wavelengths full");
    return 0;
  }
  std::size_t used = 0;
  int n = -1;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
  }
  if (used != text.size() || n < 1 || n > 16) {
    throw std::runtime_error(std::string("expected 1..16") + (full_allowed ? " or full" : "") +
                             ", not '" + text + "'");
  }
  return n;
}

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && !std::isfinite(value))
          return "Value " + text + " is not a finite number";
        return {};
      },
      "FINITE");
}

CLI::Option* add_size_option(CLI::App& cmd, std::optional<CanvasSize>& size,
                             std::string_view detail, bool old_square_number) {
  return cmd
      .add_option_function<std::string>(
          "--size", [&size](const std::string& text) { size = parse_canvas_size(text); },
          vocabulary_help("--size", detail))
      ->type_name("WxH")
      ->transform(parsing_check("", [old_square_number](const std::string& text) {
        if (old_square_number && !text.empty() && text.find('x') == std::string::npos) {
          const std::string square = text + "x" + text;
          parse_canvas_size(square);
          warn("--size " + text + " is deprecated: use --size " + square);
          return square;
        }
        parse_canvas_size(text);
        return text;
      }));
}

CLI::Option* add_dpi_option(CLI::App& cmd, std::optional<double>& dpi, std::string_view detail) {
  return cmd.add_option("--dpi", dpi, vocabulary_help("--dpi", detail))
      ->check(finite_range(1.0, 20000.0));
}

CLI::Option* add_dpi_option(CLI::App& cmd, double& dpi, std::string_view detail, double min_dpi,
                            double max_dpi) {
  return cmd.add_option("--dpi", dpi, vocabulary_help("--dpi", detail))
      ->check(finite_range(min_dpi, max_dpi))
      ->capture_default_str();
}

CLI::Option* add_wavelengths_option(CLI::App& cmd, int& nodes, bool full_allowed,
                                    std::string_view detail) {
  const std::string default_text = nodes == 0 ? "full" : std::to_string(nodes);
  return cmd.add_option("--wavelengths", nodes, vocabulary_help("--wavelengths", detail))
      ->type_name(full_allowed ? "1..16|full" : "1..16")
      ->transform(parsing_check("",
                                [full_allowed](const std::string& text) {
                                  return std::to_string(parse_wavelengths(text, full_allowed));
                                }))
      ->default_str(default_text);
}

CLI::Option* add_out_option(CLI::App& cmd, std::string& out, std::string_view detail) {
  return cmd.add_option("-o,--out", out, vocabulary_help("-o,--out", detail))->type_name("FILE");
}

CLI::Option* add_save_option(CLI::App& cmd, std::string& save, std::string_view detail) {
  return cmd.add_option("--save", save, vocabulary_help("--save", detail))
      ->type_name("FILE.impasto");
}

CLI::Option* add_json_flag(CLI::App& cmd, bool& json, std::string_view detail) {
  return cmd.add_flag("--json", json, vocabulary_help("--json", detail));
}

CLI::Option* add_quality_option(CLI::App& cmd, std::string& quality, std::string_view detail) {
  std::string help =
      "How finely the simulation steps a brush: exact (a cell at a time), balanced or fast "
      "(quicker on big brushes, a faint ripple; docs/simulation.md, Quality)";
  if (!detail.empty()) help += "; " + std::string(detail);
  return cmd.add_option("--quality", quality, help)
      ->check(CLI::IsMember(util::names_of(paintcore::kStepQualityNames)));
}

CLI::Option* add_threads_option(CLI::App& cmd, int& threads) {
  return cmd.add_option("--threads", threads, vocabulary_help("--threads", {}))
      ->check(finite_range(0, 1024));
}

CLI::Option* add_deprecated_option(CLI::App& cmd, const std::string& old_name,
                                   const std::string& use_instead,
                                   std::function<void(const std::string&)> apply) {
  const std::string name = old_name;
  return cmd
      .add_option_function<std::string>(
          old_name,
          [name, use_instead, apply](const std::string& value) {
            warn(name + " is deprecated: use " + use_instead);
            apply(value);
          },
          "Deprecated: use " + use_instead)
      ->group("");  // hidden from --help
}

CLI::Option* add_deprecated_flag(CLI::App& cmd, const std::string& old_name,
                                 const std::string& use_instead, std::function<void()> apply) {
  const std::string name = old_name;
  return cmd
      .add_flag_function(
          old_name,
          [name, use_instead, apply](std::int64_t) {
            warn(name + " is deprecated: use " + use_instead);
            apply();
          },
          "Deprecated: use " + use_instead)
      ->group("");
}

void add_quiet_option(CLI::App& root) {
  if (root.get_option_no_throw("--quiet") == nullptr) {
    root.add_flag_function(
            "-q,--quiet", [](std::int64_t count) { set_quiet(count > 0); },
            vocabulary_help("-q,--quiet", {}))
        ->trigger_on_parse();
  }
  for (CLI::App* sub : root.get_subcommands([](CLI::App*) { return true; })) add_quiet_option(*sub);
}

}  // namespace impasto::app
