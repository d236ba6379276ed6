#pragma once
// Flake paint in the tile renderer: the sparkles of metallic and pearlescent pigments
// (impasto::flakes, Ershov, Khodulev, Kolchin §5.3) added to the shaded colour of the cells
// whose top paint layer holds them. The effect costs nothing where it is absent: the tile
// renderer makes no FlakeShading when no pigment of the palette carries flakes, and a tile
// whose layers hold no flake pigment gets an inactive FlakeTileView (checked once per tile).
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "impasto/flakes/sparkle_lights.hpp"
#include "impasto/flakes/sparkles.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render {

// The main light of `settings` as the sparkle model sees it, for a canvas of the given size
// (mm). Point and spot lights stand light_distance_mm from the canvas centre in the light
// direction (the spot aims at the centre). Its strength (one value per node) puts sparkle
// radiance in the renderer's units: 1 is a white Lambertian surface lying flat under the
// direct part (1 − ambient) of the light, as shade::blinn_phong normalises its diffuse term.
flakes::Light sparkle_light(const RenderSettings& settings, double canvas_width_mm,
                            double canvas_height_mm, int nodes);

class FlakeTileView;

class FlakeShading {
 public:
  // One sparkle renderer per flake pigment of the palette (its *.flake file read and
  // tabulated for the palette's nodes), or nullptr when there is nothing to do: flakes off,
  // diffuse light, or no pigment with flakes. Throws std::runtime_error naming a bad file.
  static std::unique_ptr<FlakeShading> create(const RenderSettings& settings,
                                              const SpectralPalette& palette);

  struct FlakePigment {
    int slot;  // painting slot = palette pigment index
    flakes::SparkleRenderer sparkles;
  };
  const std::vector<FlakePigment>& pigments() const { return pigments_; }
  int nodes() const { return nodes_; }

  // The flake paint of one tile: inactive (no per-cell work) when neither its wet layer nor
  // any dry layer there holds a flake pigment.
  FlakeTileView tile(const paintcore::Canvas& canvas, int tile_index) const;

  // Node radiance (renderer units) to display-referred XYZ: the palette's weights.
  void add_xyz(const double* node_radiance, float xyz[3]) const;

 private:
  FlakeShading(const RenderSettings& settings, const SpectralPalette& palette);

  RenderSettings settings_;
  int nodes_ = 0;
  std::vector<FlakePigment> pigments_;
  std::vector<float> to_xyz_;  // 3 rows of nodes_
};

// The flake pigments of one tile and the light over it. Made once per shaded region, used by
// one thread.
class FlakeTileView {
 public:
  FlakeTileView() = default;  // inactive

  bool active() const { return shading_ != nullptr; }

  // Adds the sparkles of local cell `cell` (canvas cell canvas_x, canvas_y) to its XYZ.
  // Only the top paint layer of the cell counts: the wet paint where there is some, else
  // the topmost dry layer with paint; its flake concentration is amount / volume and the
  // flakes fill its thickness. Returns the number of sparkles.
  int add_cell(int cell, int canvas_x, int canvas_y, shade::Vec3 normal, float surface_height_mm,
               float wet_volume_mm, float xyz[3]);

  // The top paint layer of local cell `cell`: its thickness (mm, 0 on bare canvas) and the
  // concentration of each flake pigment of the shading in it (pigments().size() values).
  float top_layer(int cell, float wet_volume_mm, std::span<float> concentrations) const;

  // Cells looked at since the view was made (a cost counter for tests and profiling).
  std::uint64_t cells_evaluated() const { return cells_evaluated_; }

 private:
  friend class FlakeShading;
  static constexpr std::size_t kMaxFlakePigments = paintcore::kMaxPigmentSlots;
  // Amounts (mm) of each flake pigment of the shading in one layer; nullptr where absent.
  using Amounts = std::array<const float*, kMaxFlakePigments>;
  struct DryLayer {
    const float* volume_mm;
    Amounts amounts;
  };

  const FlakeShading* shading_ = nullptr;
  flakes::Light light_;
  double cell_mm_ = 0;
  Amounts wet_{};
  std::vector<DryLayer> dry_;  // top first: every dry layer with paint in the tile
  std::vector<double> radiance_;
  std::uint64_t cells_evaluated_ = 0;
};

}  // namespace impasto::render
