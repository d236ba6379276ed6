#pragma once
// The command line's shared words: an option means the same thing in every sub-command that
// has it (docs/cli.md). Each add_* below is the one place where an option's name and meaning
// are written; choices come from the enums' name tables (util::EnumNames). `impasto help
// vocabulary` prints the reference that docs/cli.md holds, and a test compares the two.
#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/util/enum_names.hpp"
#include "vocabulary_words.hpp"

namespace impasto::app {

// The shared options. `detail` is added after the shared meaning (": ..."), for what this
// command does with it.
// old_square_number: a bare N (the old spelling of a square canvas) is NxN, with a warning.
// A value that is a number refuses NaN and infinities ("nan", "inf"): CLI11's Range lets NaN
// through, every comparison with it being false.
CLI::Validator finite_number();
// CLI::Range(min, max) that also refuses NaN and infinities, with Range's own description
// ("FLOAT in [0 - 1]"): the range check of every numeric option.
template <typename T>
CLI::Validator finite_range(T min, T max) {
  const CLI::Validator range = CLI::Range(min, max);
  CLI::Validator checked = range & finite_number();
  checked.description(range.get_description());
  return checked;
}

CLI::Option* add_size_option(CLI::App& cmd, std::optional<CanvasSize>& size,
                             std::string_view detail = {}, bool old_square_number = false);
CLI::Option* add_dpi_option(CLI::App& cmd, std::optional<double>& dpi,
                            std::string_view detail = {});
CLI::Option* add_dpi_option(CLI::App& cmd, double& dpi, std::string_view detail = {},
                            double min_dpi = 1.0, double max_dpi = 20000.0);
// nodes: 1..16, or 0 for "full" where full_allowed (else "full" is refused at parse time).
CLI::Option* add_wavelengths_option(CLI::App& cmd, int& nodes, bool full_allowed,
                                    std::string_view detail = {});
CLI::Option* add_out_option(CLI::App& cmd, std::string& out, std::string_view detail);
// --light-dir AZIMUTH,ELEVATION in degrees (parse_light_direction reads it).
CLI::Option* add_light_dir_option(CLI::App& cmd, std::string& light_dir);
CLI::Option* add_save_option(CLI::App& cmd, std::string& save, std::string_view detail = {});
CLI::Option* add_json_flag(CLI::App& cmd, bool& json, std::string_view detail);
// --quality LEVEL: exact, balanced or fast (paintcore::kStepQualityNames).
CLI::Option* add_quality_option(CLI::App& cmd, std::string& quality, std::string_view detail = {});
CLI::Option* add_threads_option(CLI::App& cmd, int& threads);

// An option whose value is one of an enum's names (CLI11 checks it; the help lists them).
template <typename Enum, std::size_t N>
CLI::Option* add_choice_option(CLI::App& cmd, const std::string& name, std::string& value,
                               const util::EnumNames<Enum, N>& names, const std::string& help) {
  return cmd.add_option(name, value, help)
      ->check(CLI::IsMember(util::names_of(names)))
      ->capture_default_str();
}

// An old spelling kept for scripts: hidden from --help; when given, warns "OLD is deprecated:
// use NEW" and hands its value to `apply`.
CLI::Option* add_deprecated_option(CLI::App& cmd, const std::string& old_name,
                                   const std::string& use_instead,
                                   std::function<void(const std::string&)> apply);
CLI::Option* add_deprecated_flag(CLI::App& cmd, const std::string& old_name,
                                 const std::string& use_instead, std::function<void()> apply);

// --quiet on root and every sub-command (as --pigments): set before any command runs.
void add_quiet_option(CLI::App& root);

}  // namespace impasto::app
