#pragma once
// One IMPaSTo simulation step on the brush's window of canvas cells (Fig. 5):
// gather the window from the tiles, penetration, velocity, advection, transfer, scatter.
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "impasto/paintcore/advection.hpp"
#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/brush_pose.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::paintcore {

class Stepper {
 public:
  // Called with a tile index before the step first changes or creates that tile.
  using BeforeTileChange = std::function<void(int tile_index)>;

  // Runs one step with the brush at `pose`, having moved by (move_x, move_y) cells since the
  // previous step (|move| <= 1, the CFL limit). Returns false, changing nothing, when the
  // brush touches no paint surface. Call inside the painting's task arena.
  bool step(Canvas& canvas, Brush& brush, int slot_count, const SimulationParams& params,
            const BrushPose& pose, double move_x, double move_y,
            const BeforeTileChange& before_change);

  std::size_t last_window_cells() const { return last_window_cells_; }

 private:
  struct Window {
    int x0 = 0, y0 = 0, width = 0, height = 0;  // canvas cells
    int stride() const { return width + 2; }
    std::size_t padded() const {
      return static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
    }
  };

  void resize(const Window& w, int slot_count, std::size_t brush_cells);
  const float* base_heights(const Canvas& canvas, int tile_index);
  void gather(const Canvas& canvas, int slot_count);
  int penetrate(const Canvas& canvas, const Brush& brush, const BrushPlacement& placement,
                double depth_mm);
  void velocity(const Canvas& canvas, const SimulationParams& params, double move_x, double move_y);
  void transfer(Brush& brush, int slot_count, const SimulationParams& params, double speed);
  void scatter(Canvas& canvas, int slot_count, const BeforeTileChange& before_change);

  Window win_;
  std::size_t last_window_cells_ = 0;
  // Padded window grids (see advection.hpp for the layout).
  std::vector<float> ground_, wet_, pen_, vx_, vy_, new_wet_;
  std::vector<float> pigment_, new_pigment_;  // slot-major, padded grids
  // Unpadded per-cell data of the transfer.
  std::vector<std::int32_t> brush_cell_;   // brush cell touching each window cell, or -1
  std::vector<float> xfer_;                // paint height moved brush -> canvas (signed)
  std::vector<float> xfer_ratio_;          // xfer_ / the source's paint height
  std::vector<float> xfer_pigment_;        // pigment moved brush -> canvas, slot-major
  std::vector<std::int32_t> brush_share_;  // canvas cells touching each brush cell
  std::vector<int> row_contacts_;
  Advection advection_;
  // Weave heights of tiles that were never painted, so hovering costs no tile memory.
  std::unordered_map<int, std::vector<float>> base_cache_;
};

}  // namespace impasto::paintcore
