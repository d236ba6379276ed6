#pragma once
// The renderer's crack hook (docs/cracks.md, "Rendering hooks"). In a cracked cell the
// cavity's apparent reflectance rho = 1 - eps (Gouffe, per wavelength node, its walls of
// reflectance rho0 = the exposed layer's: the canvas ground or the cell's baked dry stack)
// blends into the cell's reflectance by the crack's area fraction. A tile without a crack
// costs one pointer test; a canvas without cracks, one per tile.
#include <array>
#include <memory>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/crack_layer.hpp"
#include "impasto/render/render_settings.hpp"

namespace impasto::cracks {
class CavityCorrection;
}

namespace impasto::render {

// The share of the light a crack's opening receives from the sky, which decides how the
// axial and the diffuse correction tables blend: the ambient share, or all of it under a
// diffuse (overcast) light.
double crack_sky_share(const RenderSettings& settings);

// The correction for the settings' light (cracks/cavity_correction.hpp: the shipped tables
// blended for the sun's zenith and the sky's share) as the GPU uploads it: differences
// rho_table - rho_Gouffe, rho0_count per row, ratio_count rows per shape, shapes in
// CavityShape order; and F, G of each shape at the deepest row (for the decay beyond it).
struct CrackTableData {
  int ratio_count = 0;
  int rho0_count = 0;
  std::vector<float> differences;  // [shape][L/R][rho0]
  std::array<float, paintcore::kCrackShapeCount> last_F{}, last_G{};
  double sun_zenith_deg = 0.0, sky_share = 0.0;  // the light it was blended for
};
CrackTableData crack_table_data(const RenderSettings& settings);
// The sun zenith and sky share crack_table_data blends for (cheap: to see whether it changed).
std::array<double, 2> crack_table_data_light(const RenderSettings& settings);

// What the far-view blend of one cracked cell needs: the area fraction c of its opening,
// Gouffe's view factors F and G of its shape and size, and where its shape and L/R fall in
// the correction table (the GPU path uploads these).
struct CrackOptics {
  float coverage = 0.0f;
  float F = 1.0f;
  float G = 1.0f;
  bool exposes_ground = true;
  int shape = 0;          // cracks::CavityShape
  float table_u = -1.0f;  // CavityTable::ratio_coordinate, clamped to [-1, ratio_count]
};
CrackOptics crack_optics(const paintcore::CrackRecord& record, double cell_mm);

// The cracks of one canvas tile as the CPU shading loop sees them.
class CrackTileShading {
 public:
  // `ground`: the ground reflectance per node (`nodes` values). Inactive where the tile has
  // no crack or settings.cracks is false.
  CrackTileShading(const paintcore::Canvas& canvas, int tile_index, const RenderSettings& settings,
                   const float* ground, int nodes);

  bool active() const { return tile_ != nullptr; }
  // Call with the cell's dry stack (per node, before the wet layer): returns whether the
  // cell is cracked and, if so, keeps its walls' reflectance for blend().
  bool take_walls(int cell, const float* dry_stack);
  // reflectance = (1 - c) reflectance + c rho(walls; F, G), per node, for the cell whose walls
  // take_walls kept last.
  void blend(float* reflectance) const;

 private:
  const paintcore::CrackTile* tile_ = nullptr;
  double cell_mm_;
  std::shared_ptr<const cracks::CavityCorrection> correction_;  // null: Gouffé's closed form
  const float* ground_;
  int nodes_;
  std::vector<float> walls_;
  const paintcore::CrackRecord* record_ = nullptr;
};

}  // namespace impasto::render
