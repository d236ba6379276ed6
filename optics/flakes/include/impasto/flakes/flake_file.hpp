#pragma once
// Reading flake paints (*.flake) and metal optical constants (n, k tables); the formats are
// described in docs/flakes.md. Errors name the file and line or the missing field.
#include <filesystem>
#include <string>

#include "impasto/flakes/flake_paint.hpp"

namespace impasto::flakes {

// Reads a flake paint file; an n, k table it names is read relative to the file's folder.
FlakePaint load_flake_paint(const std::filesystem::path& file);

// Parses a flake paint from text; `origin` names it in error messages and relative paths
// are resolved against `folder`.
FlakePaint parse_flake_paint(const std::string& text, const std::string& origin,
                             const std::filesystem::path& folder);

// Reads a CSV table `wavelength_nm,n,k` (lines starting with # are comments) into a metal
// coating.
FlakeCoating load_nk_table(const std::filesystem::path& file);
FlakeCoating parse_nk_table(const std::string& text, const std::string& origin);

}  // namespace impasto::flakes
