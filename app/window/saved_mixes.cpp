#include "window/saved_mixes.hpp"

#include <impasto/util/text.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "impasto/files/message_text.hpp"
#include "impasto/session/recent_files.hpp"
#include "window/config_files.hpp"

namespace impasto::app::window {
namespace {

constexpr std::string_view kMixesHeader = "impasto-mixes 1";
constexpr float kMaxParts = 1000.0f;
// A file larger than this is not a list of mixes (64 mixes of 30 pigments take some 60 kB).
constexpr std::size_t kMixesMaxBytes = 1 << 20;

bool known_pigment(const std::vector<std::string>& known, const std::string& name) {
  return std::find(known.begin(), known.end(), name) != known.end();
}

}  // namespace

SavedMixes parse_saved_mixes(std::string_view text, const std::string& source,
                             const std::vector<std::string>& known) {
  SavedMixes out;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0;
  const auto where = [&] { return source + ":" + std::to_string(number) + ": "; };
  const auto drop_empty_last = [&] {
    if (!out.mixes.empty() && out.mixes.back().parts.empty()) {
      out.warnings.push_back(source + ": mix '" + files::terminal_text(out.mixes.back().name) +
                             "' has no pigment this library knows: left out");
      out.mixes.pop_back();
    }
  };
  while (std::getline(in, line)) {
    ++number;
    const std::string_view trimmed = util::trim(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    if (number == 1 || trimmed == kMixesHeader) {
      if (trimmed != kMixesHeader)
        throw std::runtime_error(where() + "expected '" + std::string(kMixesHeader) + "'");
      continue;
    }
    if (trimmed.starts_with("mix ")) {
      drop_empty_last();
      if (out.mixes.size() == kMaxSavedMixes) {
        out.warnings.push_back(where() + "more than " + std::to_string(kMaxSavedMixes) +
                               " mixes: the rest are left out");
        return out;
      }
      out.mixes.push_back({util::line_decoded(util::trim(trimmed.substr(4))), {}});
      continue;
    }
    if (trimmed.starts_with("part ")) {
      if (out.mixes.empty()) throw std::runtime_error(where() + "a part before any mix");
      const std::string_view rest = util::trim(trimmed.substr(5));
      const std::size_t space = rest.find(' ');
      float parts = 0.0f;
      try {
        std::size_t used = 0;
        parts = std::stof(std::string(rest.substr(0, space)), &used);
        if (used != rest.substr(0, space).size()) parts = -1.0f;
      } catch (const std::exception&) {
        parts = -1.0f;
      }
      if (!(parts > 0.0f && parts <= kMaxParts) || space == std::string_view::npos)
        throw std::runtime_error(where() + "expected 'part PARTS PIGMENT', PARTS in (0, 1000]");
      const std::string pigment = util::line_decoded(util::trim(rest.substr(space + 1)));
      if (!known_pigment(known, pigment)) {
        out.warnings.push_back(where() + "no pigment '" + files::terminal_text(pigment) +
                               "' in this library: that part is left out");
        continue;
      }
      out.mixes.back().parts.emplace_back(pigment, parts);
      continue;
    }
    throw std::runtime_error(where() + "expected 'mix NAME' or 'part PARTS PIGMENT', got '" +
                             files::terminal_text(std::string(trimmed.substr(0, 40))) + "'");
  }
  drop_empty_last();
  return out;
}

std::string format_saved_mixes(const std::vector<SavedMix>& mixes) {
  std::string text = std::string(kMixesHeader) + "\n";
  for (const SavedMix& mix : mixes) {
    text += "mix " + util::line_encoded(mix.name) + "\n";
    for (const auto& [pigment, parts] : mix.parts)
      text += "part " + util::number_text(parts) + " " + util::line_encoded(pigment) + "\n";
  }
  return text;
}

std::filesystem::path saved_mixes_path() {
  const std::filesystem::path folder = session::window_config_folder();
  return folder.empty() ? folder : folder / "mixes.txt";
}

SavedMixes load_saved_mixes(const std::vector<std::string>& known) {
  std::string warning;
  const std::string text = read_config_text("mixes.txt", kMixesMaxBytes, warning);
  if (!warning.empty()) return {{}, {warning + ": no saved mixes loaded"}};
  try {
    return parse_saved_mixes(text, saved_mixes_path().string(), known);
  } catch (const std::exception& e) {
    return {{}, {std::string(e.what()) + " (no saved mixes loaded)"}};
  }
}

void store_saved_mixes(const std::vector<SavedMix>& mixes) {
  write_config_text("mixes.txt", format_saved_mixes(mixes));
}

SavedMix saved_mix(std::string name, const std::vector<float>& mix_parts,
                   const std::vector<std::string>& known) {
  SavedMix mix{std::move(name), {}};
  for (std::size_t i = 0; i < mix_parts.size() && i < known.size(); ++i)
    if (mix_parts[i] > 0.0f) mix.parts.emplace_back(known[i], mix_parts[i]);
  return mix;
}

std::vector<float> mix_parts_of(const SavedMix& mix, const std::vector<std::string>& known) {
  std::vector<float> parts(known.size(), 0.0f);
  for (const auto& [pigment, amount] : mix.parts) {
    const auto it = std::find(known.begin(), known.end(), pigment);
    if (it != known.end()) parts[static_cast<std::size_t>(it - known.begin())] = amount;
  }
  return parts;
}

std::string mix_description(const SavedMix& mix) {
  std::string text;
  for (const auto& [pigment, parts] : mix.parts)
    text += (text.empty() ? "" : " + ") + util::number_text(parts, 3) + " " + pigment;
  return text;
}

}  // namespace impasto::app::window
