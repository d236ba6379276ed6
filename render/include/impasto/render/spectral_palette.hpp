#pragma once
// What the renderer needs for one light: the wavelength nodes, the pigments' K and S and the
// ground's reflectance at those nodes, and the weights that turn node reflectances into
// display-referred XYZ. Rebuilt when the light, the node count or the pigments change.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

class SpectralPalette {
 public:
  // The light from settings.light, the pigments by name from the default database, the
  // ground from settings.ground (or white's R∞). Throws std::runtime_error naming
  // an unknown light or pigment.
  SpectralPalette(const RenderSettings& settings, std::span<const std::string> pigment_names);
  // Pigments a painting carries (render/pigment_records.hpp) by name; the rest, and the
  // ground's white when it is not among them, from the default database.
  using CarriedPigments = std::shared_ptr<const std::map<std::string, data::Pigment>>;
  SpectralPalette(const RenderSettings& settings, std::span<const std::string> pigment_names,
                  CarriedPigments carried);
  // The pigments by name with a rule already made (another palette's: a chip of a paint shown
  // under the painting's own rule, as the canvas shows it). The rule must be for
  // settings.light; its nodes and weights are taken as they are.
  SpectralPalette(const RenderSettings& settings, std::span<const std::string> pigment_names,
                  const SpectralSampling& rule);
  // The painting's slots with the pigments it carries (bit-identical without the library).
  SpectralPalette(const RenderSettings& settings, const paintcore::Painting& painting);
  // The same from explicit data (tests, benchmarks, files).
  SpectralPalette(const RenderSettings& settings, const data::Spectrum& light,
                  std::vector<data::Pigment> pigments, const data::Spectrum& ground);

  int nodes() const { return sampling_.size(); }
  int pigment_count() const { return static_cast<int>(pigment_names_.size()); }
  const std::vector<std::string>& pigment_names() const { return pigment_names_; }
  const CarriedPigments& carried() const { return carried_; }
  const SpectralSampling& sampling() const { return sampling_; }

  // K and S of a pigment at every node (nodes() values each).
  const float* absorption(int pigment) const { return &absorption_[offset(pigment)]; }
  const float* scattering(int pigment) const { return &scattering_[offset(pigment)]; }
  // The canvas ground's reflectance at every node.
  const float* ground() const { return ground_.data(); }
  // The flake paint file of a pigment (data::Pigment::flakes), empty when it has no flakes.
  const std::filesystem::path& flake_file(int pigment) const {
    return flake_files_[static_cast<std::size_t>(pigment)];
  }

  // Node reflectances to display-referred XYZ (Y = 1 for white; chromatic adaptation
  // included): xyz[c] = Σ_i to_display_xyz(c)[i] R_i. One row per channel, for vector loops.
  const float* to_display_xyz(int channel) const { return &to_xyz_[offset(channel)]; }
  // What a perfect white reflector shows as (also the colour of specular highlights).
  const std::array<float, 3>& white_xyz() const { return white_xyz_; }

 private:
  std::size_t offset(int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(nodes());
  }
  // With `rule` null, the rule settings ask for (make_palette_sampling); else that one.
  void build(const RenderSettings& settings, const data::Spectrum& light,
             const std::vector<data::Pigment>& pigments, const data::Spectrum& ground,
             const SpectralSampling* rule = nullptr);

  SpectralSampling sampling_;
  std::vector<std::string> pigment_names_;
  CarriedPigments carried_;
  std::vector<float> absorption_, scattering_;  // pigment-major, nodes() per pigment
  std::vector<float> ground_;
  std::vector<std::filesystem::path> flake_files_;  // one per pigment
  std::vector<float> to_xyz_;                       // 3 rows of nodes()
  std::array<float, 3> white_xyz_{};
};

// The reflectance of an opaque layer of `pigment` (R∞ at every wavelength of its data): the
// default canvas ground when the pigment is white.
data::Spectrum hiding_reflectance(const data::Pigment& pigment);

}  // namespace impasto::render
