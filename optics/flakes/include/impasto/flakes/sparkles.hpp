#pragma once
// Sparkles of flake paint for the CPU renderer (Ershov, Khodulev, Kolchin §5.3): for a canvas
// cell, how many flakes mirror a light into the eye (a Poisson count from the flake
// statistics), and the radiance their energy gives when spread over the cell.
//
// The sparkle radiance is the flakes' specular lobe made discrete: its mean over cells is
// exactly mean_radiance(), the smooth flake BRDF term, and it is never negative. A renderer
// adds it to the diffuse K-M colour and the binder highlight, in place of that lobe.
#include <cstddef>
#include <cstdint>
#include <span>

#include "impasto/flakes/counter_rng.hpp"
#include "impasto/flakes/flake_tables.hpp"
#include "impasto/flakes/sparkle_lights.hpp"

namespace impasto::flakes {

struct SparkleSettings {
  // Paper §5.3.2: with masking/shadowing every depth holds sparkles and their light is
  // attenuated as e^{−tz}; without it, fewer flakes are visible, unattenuated.
  enum class DepthModel { with_masking, without_masking };
  DepthModel depth_model = DepthModel::with_masking;
  // Flakes are told apart by the slope (n_f.x / n_f.z, n_f.y / n_f.z) of the mirroring
  // normal on a grid of this step. The default is about the cone of flake normals that
  // mirror the sun (Δ / η wide in the binder), so a light moving by a fraction of its own
  // size keeps most sparkles and one moving by its size lights new ones.
  double orientation_cell = 3e-3;
  std::uint32_t seed = 0;
};

// One canvas cell holding (some) flake paint.
struct FlakeCell {
  std::int32_t ix = 0, iy = 0;     // cell index on the canvas: keys its random numbers
  Vec3 center_mm{};                // cell centre; z is the paint surface height
  Vec3 normal{0, 0, 1};            // paint surface normal (unit)
  double area_mm2 = 0;             // Σ projected on the canvas plane
  double flake_concentration = 0;  // fraction of the flake paint (1 = as in its file)
  double thickness_mm = 0;         // H, the paint holding the flakes (vertical)
};

// A rectangle of cells in row-major arrays (the renderer's tile). Spans may be empty where
// noted; all others hold width × height values.
struct FlakeTile {
  std::int32_t first_ix = 0, first_iy = 0;  // canvas index of the first cell
  int width = 0, height = 0;
  double cell_size_mm = 0;                   // cells are squares
  std::span<const float> concentration;      // flake paint fraction per cell
  std::span<const float> thickness_mm;       // paint thickness per cell
  std::span<const float> surface_height_mm;  // empty: 0
  std::span<const float> normals;            // 3 per cell (x, y, z); empty: (0, 0, 1)
};

// Immutable after construction: its const methods may run on many threads at once.
class SparkleRenderer {
 public:
  SparkleRenderer(const FlakePaint& paint, std::span<const double> wavelengths_nm,
                  SparkleSettings settings = {});

  const FlakeTables& tables() const { return tables_; }
  const SparkleSettings& settings() const { return settings_; }
  // Mean and deviation of ln S, the log-normal flake areas (the GPU port draws the same).
  double log_area_mean() const { return log_area_mean_; }
  double log_area_sd() const { return log_area_sd_; }

  // Adds the sparkle radiance of one cell under one light, per wavelength node, to
  // `radiance` (size = wavelength count). Returns the number of sparkles.
  int add_cell(const FlakeCell& cell, const Light& light, const View& view,
               std::span<double> radiance) const;

  // The expected number of sparkles ⟨N⟩ in the cell (Eq. 5 or 6).
  double expected_count(const FlakeCell& cell, const Light& light, const View& view) const;

  // Adds the expected sparkle radiance (the flake BRDF term) per wavelength to `radiance`.
  void add_mean_radiance(const FlakeCell& cell, const Light& light, const View& view,
                         std::span<double> radiance) const;

  // Adds the sparkle radiance of every cell under all lights to `radiance` (row-major,
  // wavelength nodes innermost: width × height × wavelength count). Returns the number of
  // cells that held flakes; a tile without flakes returns 0 at once and writes nothing.
  // Throws std::runtime_error naming the cell for NaN or negative input.
  std::size_t add_tile(const FlakeTile& tile, std::span<const Light> lights, const View& view,
                       std::span<float> radiance) const;

 private:
  struct Setup;
  bool prepare(const FlakeCell& cell, const Light& light, const View& view, Setup& s) const;
  double optical_thickness(const Setup& s) const;
  double radiance_per_area(const Setup& s) const;
  // Σ S·e^{−tz} over `count` sparkles: areas log-normal with the paint's mean and deviation,
  // depths uniform in [0, depth] (with masking only).
  double flake_weight(CounterRng& rng, int count, double t_per_depth, double depth) const;

  FlakeTables tables_;
  SparkleSettings settings_;
  double log_area_mean_ = 0, log_area_sd_ = 0;  // of ln S
};

}  // namespace impasto::flakes
