#pragma once
// The pigment database: one spectral CSV per pigment (docs/pigments.md) holding its
// Kubelka–Munk absorption K and scattering S (per unit thickness, S relative to white's).
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/data/spectrum.hpp"

namespace impasto::data {

struct Pigment {
  std::string name;
  Spectrum K, S;                                // same wavelength grid, both >= 0
  std::map<std::string, std::string> metadata;  // every "# key: value" of its file
  // Metallic or pearlescent flakes carried by the paint: the *.flake file named by the
  // '# flakes:' line (relative to the pigment file), made absolute; empty when it has none.
  std::filesystem::path flakes{};
};

// Reads one pigment file: '# quantity: kubelka_munk', '# name:', columns K and S (other
// columns and metadata keys are allowed and ignored here), and '# flakes: FILE' when the
// paint carries flakes. Throws std::runtime_error naming the file and field.
Pigment read_pigment_file(const std::filesystem::path& path);
// Writes a pigment in the same format (its metadata, name and K, S on K's grid).
void write_pigment_file(const std::filesystem::path& path, const Pigment& pigment);
// A file name for a pigment: lower case, runs of other characters as '_', ".csv".
std::string pigment_file_name(std::string_view pigment_name);

class PigmentDatabase {
 public:
  // Every *.csv in dir, sorted by file name. Throws on a bad file or a repeated name.
  static PigmentDatabase load(const std::filesystem::path& dir);
  // These pigments (names must be unique).
  static PigmentDatabase from_pigments(std::vector<Pigment> pigments);
  // The active layered library's pigments (pigment_library.hpp): data_dir()/pigments, the
  // user's folder and --pigments folders; loaded once (thread-safe).
  static const PigmentDatabase& defaults();

  // Exact name first, then case-insensitive. Throws with the list of names.
  const Pigment& get(std::string_view name) const;
  const Pigment* find(std::string_view name) const;
  const std::vector<Pigment>& all() const { return pigments_; }

 private:
  std::vector<Pigment> pigments_;
};

}  // namespace impasto::data
