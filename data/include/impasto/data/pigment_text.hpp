#pragma once
// A pigment file's text without the file: what a painting carries of each pigment it uses
// (render/pigment_records.hpp) and what the editor validates as one types.
#include <string>
#include <string_view>

#include "impasto/data/pigments.hpp"

namespace impasto::data {

// The text write_pigment_file writes (shortest round-trip numbers: parsing gives the same
// doubles back).
std::string format_pigment_text(const Pigment& pigment);
// Parses and checks as read_pigment_file does ('# quantity: kubelka_munk', '# name:', K and
// S >= 0), `source` standing for the file in messages. A '# flakes:' line is kept in metadata
// but not resolved: Pigment::flakes stays empty (the caller knows where flake files are).
Pigment parse_pigment_text(std::string_view text, const std::string& source);

}  // namespace impasto::data
