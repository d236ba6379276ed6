#pragma once
// The renderer's crack hook (docs/cracks.md, "Rendering hooks"). In a cracked cell the
// cavity's apparent reflectance rho = 1 - eps (Gouffe, per wavelength node, its walls of
// reflectance rho0 = the exposed layer's: the canvas ground or the cell's baked dry stack)
// blends into the cell's reflectance by the crack's area fraction. A tile without a crack
// costs one pointer test; a canvas without cracks, one per tile.
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/crack_layer.hpp"

namespace impasto::render {

// What the far-view blend of one cracked cell needs: the area fraction c of its opening and
// Gouffe's view factors F and G of its shape and size (the GPU path uploads these).
struct CrackOptics {
  float coverage = 0.0f;
  float F = 1.0f;
  float G = 1.0f;
  bool exposes_ground = true;
};
CrackOptics crack_optics(const paintcore::CrackRecord& record, double cell_mm);

// The cracks of one canvas tile as the CPU shading loop sees them.
class CrackTileShading {
 public:
  // `ground`: the ground reflectance per node (`nodes` values). Inactive where the tile has
  // no crack or `enabled` is false.
  CrackTileShading(const paintcore::Canvas& canvas, int tile_index, bool enabled,
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
  const float* ground_;
  int nodes_;
  std::vector<float> walls_;
  const paintcore::CrackRecord* record_ = nullptr;
};

}  // namespace impasto::render
