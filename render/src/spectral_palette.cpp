#include "impasto/render/spectral_palette.hpp"

#include <cmath>
#include <stdexcept>

#include "impasto/data/cie.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/render/kubelka_munk_cell.hpp"
#include "impasto/render/node_optimisation.hpp"
#include "impasto/render/pigment_records.hpp"

namespace impasto::render {
namespace {

constexpr const char* kGroundPigment = "White";

}  // namespace

data::Spectrum hiding_reflectance(const data::Pigment& pigment) {
  data::Spectrum reflectance{pigment.name + " (opaque)", pigment.K.wavelengths_nm, {}};
  reflectance.values.reserve(reflectance.wavelengths_nm.size());
  for (double nm : reflectance.wavelengths_nm) {
    reflectance.values.push_back(km::reflectance_infinite(static_cast<float>(pigment.K.at(nm)),
                                                          static_cast<float>(pigment.S.at(nm))));
  }
  return reflectance;
}

SpectralPalette::SpectralPalette(const RenderSettings& settings,
                                 std::span<const std::string> pigment_names)
    : SpectralPalette(settings, pigment_names, nullptr) {}

SpectralPalette::SpectralPalette(const RenderSettings& settings,
                                 std::span<const std::string> pigment_names,
                                 const SpectralSampling& rule) {
  const auto& database = data::PigmentDatabase::defaults();
  std::vector<data::Pigment> pigments;
  for (const auto& name : pigment_names) pigments.push_back(database.get(name));
  const data::Spectrum ground =
      settings.ground ? *settings.ground : hiding_reflectance(database.get(kGroundPigment));
  build(settings, data::light_from_spec(settings.light), pigments, ground, &rule);
}

SpectralPalette::SpectralPalette(const RenderSettings& settings,
                                 std::span<const std::string> pigment_names,
                                 CarriedPigments carried) {
  const auto& database = data::PigmentDatabase::defaults();
  const auto find = [&](const std::string& name) -> const data::Pigment& {
    if (carried) {
      if (const auto it = carried->find(name); it != carried->end()) return it->second;
    }
    return database.get(name);
  };
  std::vector<data::Pigment> pigments;
  for (const auto& name : pigment_names) pigments.push_back(find(name));
  const data::Spectrum ground =
      settings.ground ? *settings.ground : hiding_reflectance(find(kGroundPigment));
  build(settings, data::light_from_spec(settings.light), pigments, ground);
  carried_ = std::move(carried);
}

SpectralPalette::SpectralPalette(const RenderSettings& settings,
                                 const paintcore::Painting& painting)
    : SpectralPalette(settings, painting.pigment_slots(), carried_pigments(painting)) {}

SpectralPalette::SpectralPalette(const RenderSettings& settings, const data::Spectrum& light,
                                 std::vector<data::Pigment> pigments,
                                 const data::Spectrum& ground) {
  build(settings, light, pigments, ground);
}

void SpectralPalette::build(const RenderSettings& settings, const data::Spectrum& light,
                            const std::vector<data::Pigment>& pigments,
                            const data::Spectrum& ground, const SpectralSampling* rule) {
  validate(settings);
  sampling_ = rule ? *rule
                   : make_palette_sampling(light, data::cie1931_2deg(), settings.wavelengths,
                                           settings.range, settings.node_weights, pigments, ground);
  const auto n = static_cast<std::size_t>(nodes());

  pigment_names_.clear();
  absorption_.clear();
  scattering_.clear();
  flake_files_.clear();
  for (const auto& pigment : pigments) {
    pigment_names_.push_back(pigment.name);
    flake_files_.push_back(pigment.flakes);
    const std::vector<float> K = sample_at_nodes(pigment.K, sampling_);
    const std::vector<float> S = sample_at_nodes(pigment.S, sampling_);
    for (std::size_t i = 0; i < n; ++i) {
      if (!(K[i] >= 0.0f) || !(S[i] >= 0.0f) || !std::isfinite(K[i]) || !std::isfinite(S[i])) {
        throw std::runtime_error("pigment '" + pigment.name + "': K or S at " +
                                 std::to_string(sampling_.wavelengths_nm[i]) +
                                 " nm is negative or not finite");
      }
    }
    absorption_.insert(absorption_.end(), K.begin(), K.end());
    scattering_.insert(scattering_.end(), S.begin(), S.end());
  }

  ground_ = sample_at_nodes(ground, sampling_);
  for (float& r : ground_) {
    if (!(r >= 0.0f && r <= 1.0f)) {
      throw std::runtime_error("ground reflectance '" + ground.name + "' is outside [0, 1]");
    }
  }

  // Adaptation folded into the per-node weights: free per cell.
  const Xyz light_white = sampling_.white_xyz;
  const Matrix3 adapt = settings.adaptation == ChromaticAdaptation::bradford
                            ? bradford_matrix(light_white, kD65WhiteXyz)
                            : identity_matrix();
  to_xyz_.assign(3 * n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& w = sampling_.to_xyz[i];
    const Xyz adapted = apply(adapt, {w[0], w[1], w[2]});
    for (std::size_t c = 0; c < 3; ++c) to_xyz_[c * n + i] = static_cast<float>(adapted[c]);
  }
  const Xyz white = apply(adapt, light_white);
  white_xyz_ = {static_cast<float>(white[0]), static_cast<float>(white[1]),
                static_cast<float>(white[2])};
}

}  // namespace impasto::render
