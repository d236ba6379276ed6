#pragma once
// One IMPaSTo simulation step on the brush's window of canvas cells (Fig. 5):
// gather the window from the tiles, penetration, velocity, advection, transfer, squeeze,
// scatter. Stages that need only their own rows run fused in one row-parallel pass, so a
// step has four passes: gather to advection's shares; advection and transfer; the brush's
// side and the squeeze's faces (in fixed row chunks); the squeeze and the scatter.
#include <cstdint>
#include <functional>
#include <optional>
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

  // Runs one step with the brush at `pose`, having moved by (move_x, move_y) cells in
  // `seconds` since the previous step (|move| <= max_step_cells and the squeeze at most one
  // cell: the CFL limits, see max_step_seconds; a long step's drag is advected in sub-steps
  // of at most long_step_drag_cells travelled, and of at most a cell dragged). With lift_off the
  // brush, still, leaves the paint: the film splits fully by SimulationParams::lift_share. Returns
  // false, changing nothing, when the brush touches no paint surface. With lifting, the brush
  // rises off the paint (Painting's lift): a depth below 0 holds its tip that far above the
  // surface, where only the paint hanging under it still touches. Call inside the painting's
  // task arena.
  bool step(Canvas& canvas, Brush& brush, int slot_count, const SimulationParams& params,
            const BrushPose& pose, double move_x, double move_y, double seconds,
            const BeforeTileChange& before_change, bool lift_off = false, bool lifting = false);

  // The longest time one step may take so that the squeeze moves paint at most half a cell
  // where the penetration's slope is 1.
  static double max_step_seconds(const SimulationParams& params, double cell_mm);
  // How a step's squeeze is made on a grid of cell_mm: whole passes, each saturating at
  // `reach` (<= 1) of a full pass's limit (stepper.cpp, kReferenceCellMm).
  struct SqueezePasses {
    int passes;
    float reach;
  };
  static SqueezePasses squeeze_passes(double cell_mm);
  // The longest move of one step for this brush (paintcore::max_step_cells): a blade (a head
  // without bristles) steps a cell at a time, as its leading edge pushes the paint ahead of it cell
  // by cell (a long step's sub-steps left a blade's scrape half done).
  static double max_step_cells(const SimulationParams& params, const Brush& brush);
  // The most the tip's depth may change in one step (mm): a pen easing off, or a lift, moves
  // the contact's edge (the bristles splaying less, the underside rising) by at most half a
  // cell, or half the depth over which the film split fades in (touch_mm): an edge that
  // jumped further left the paint it stopped touching with a step, a ring in each dab. Never
  // less than a 64th of the brush's full depth.
  static double max_step_depth_mm(const SimulationParams& params, const Brush& brush);

  std::size_t last_window_cells() const { return last_window_cells_; }

  // Calls take(x_cells, y_cells, height_mm) for each canvas cell where the last step that
  // returned true moved paint between the canvas and the brush (height_mm > 0: the canvas
  // gained it from the brush; < 0: the brush took it), in a fixed order: what travels with the
  // paint (its medium, painting_surface.hpp) follows it.
  template <class Take>
  void for_each_exchange(Take&& take) const {
    if (!last_transferred_) return;
    for (int y = 0; y < win_.height; ++y) {
      const std::size_t first = static_cast<std::size_t>(y) * win_.width;
      if (swept_) {  // a long step's sub-steps: what each cell exchanged over them all
        for (int x = span_lo_[static_cast<std::size_t>(y)];
             x < span_hi_[static_cast<std::size_t>(y)]; ++x) {
          const std::size_t c = first + static_cast<std::size_t>(x);
          if (exchanged_[c] != 0.0f) take(win_.x0 + x, win_.y0 + y, exchanged_[c]);
        }
        continue;
      }
      for (int x = contact_lo_[static_cast<std::size_t>(y)];
           x < contact_hi_[static_cast<std::size_t>(y)]; ++x) {
        const std::size_t c = first + static_cast<std::size_t>(x);
        if (brush_cell_[c] >= 0 && xfer_[c] != 0.0f) take(win_.x0 + x, win_.y0 + y, xfer_[c]);
      }
    }
  }

  // A new stroke: its first step starts from its own depth.
  void begin_stroke() { last_depth_mm_.reset(); }

  // Applies what is still pending of the bristles' evening out; call when a stroke ends (and
  // so before anything else touches the brush).
  void finish_stroke(Brush& brush, int slot_count, const SimulationParams& params);

 private:
  struct Window {
    int x0 = 0, y0 = 0, width = 0, height = 0;  // canvas cells
    int stride() const { return width + 2; }
    std::size_t padded() const {
      return static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
    }
  };
  // What the row passes of one step share.
  struct StepInputs {
    const Canvas* canvas;
    const Brush* brush;
    BrushPlacement placement;
    int slot_count;
    float tip_mm;              // height of the brush tip
    float brush_vx, brush_vy;  // 1/2 the brush motion, cells/step
    float gradient_scale;      // squeeze per unit slope / (2 cell_mm): penetration difference -> v
    float min_film_mm;
    float relax;          // how far this step goes toward the film split (transfer.hpp)
    float deposit_share;  // the canvas's share of the joint film
    float inv_deposit_share;
    float tip_film_mm;   // most paint a brush cell's tips present to the canvas
    float footing_mm;    // the ground and dry paint around the brush's centre (mean)
    float ground_fill;   // how much of a valley below the footing the paint fills
    float inv_touch_mm;  // 1 / the contact depth at which the films join fully
    float surface_mm;    // the paint surface around the brush's centre (mean)
    // Canvas cells sharing a brush cell may together take more than it holds: each deposit
    // is capped by brush_share_cap_ (see step).
    bool sharing_binds;
    bool blade;  // a head without bristles (see step)
  };

  // What one step will do, decided before any row is touched.
  struct StepPlan {
    StepInputs in{};
    double drag = 0.0;        // the share of the paint the head carries (1 for a blade)
    int substeps = 1;         // a long step's sub-steps; 1 for a step of a cell or less
    SqueezePasses squeeze{};  // for the canvas's cell size
    double distance_mm = 0.0;
    double depth_from = 0.0;  // the tip's depth at the last step's end
  };
  // Places the brush, finds and sizes the window (win_, its grids and the tiles' weave), the
  // sub-steps' contact shifts and moves (shifts_, sub_moves_), and the inputs every row pass
  // shares. nullopt when the step can change nothing: no brush, no pressure, off the canvas.
  std::optional<StepPlan> plan_step(const Canvas& canvas, Brush& brush, int slot_count,
                                    const SimulationParams& params, const BrushPose& pose,
                                    double move_x, double move_y, double seconds, bool lift_off,
                                    bool lifting);
  // Paint changes only within a cell of a touching cell (the drag, the transfer and the
  // squeeze all reach one cell): each row's active span (span_lo_, span_hi_), from the rows'
  // contact and, in a long step, its sub-steps' shifted contact. Beyond it every pass would
  // give back its input bit for bit, so the passes skip it and the scatter leaves it alone.
  void find_active_spans(int rows, int cols);
  void resize(int slot_count, std::size_t brush_cells, int substeps, int squeeze_passes);
  const float* base_heights(const Canvas& canvas, int tile_index);
  void find_bases(const Canvas& canvas);
  void gather_rows(const StepInputs& in, int r0, int r1);
  void penetrate_rows(const StepInputs& in, int r0, int r1);
  void velocity_rows(const StepInputs& in, int r0, int r1);
  // A long step's sub-step's velocities, on each row's need_lo_..need_hi_ only.
  void shifted_velocity_rows(const StepInputs& in, int shift_x, int shift_y, float brush_vx,
                             float brush_vy, int r0, int r1);
  void need_shares(int rows, int cols, int quadrant_x, int quadrant_y);
  void blade_drag_rows(double move_x, double move_y, float drag, int r0, int r1);
  void transfer_rows(const StepInputs& in, int r0, int r1);
  struct Shift {
    int x, y;
  };
  bool shifted_span(int y, Shift shift, int& lo, int& hi) const;
  void shifted_transfer_rows(const StepInputs& in, Shift shift, float relax, const float* wet,
                             float* new_wet, float* new_pigment, int r0, int r1);
  void shifted_transfer_to_brush(Brush& brush, int slot_count, Shift shift, int r0, int r1);
  void squeeze_rows(const float* pen_grid, Shift shift, float c, float reach, int r0, int r1);
  void squeeze_in_passes(Shift shift, float level_offset_mm, float c, SqueezePasses plan,
                         int slot_count);
  void sub_step_penetration_rows(Shift shift, float level_offset_mm, int r0, int r1);
  void apply_squeeze_rows(int slot_count, int r0, int r1);
  void share_brush_cells(std::size_t cells, float inv_deposit_share);
  void transfer_to_brush(Brush& brush, int slot_count, int r0, int r1);
  void clamp_brush(Brush& brush, int slot_count);
  void even_out_brush(Brush& brush, int slot_count, double share);
  void copy_rows_to_tiles(Canvas& canvas, int slot_count, const float* wet, const float* pigment,
                          int r0, int r1, int only_tile) const;
  void scatter(Canvas& canvas, int slot_count, const BeforeTileChange& before_change,
               bool squeezes);

  Window win_;
  double brush_flow_pending_mm_ = 0.0;   // distance travelled since the bristles last evened out
  std::optional<double> last_depth_mm_;  // the tip's depth at the stroke's last step (pose)
  std::size_t last_window_cells_ = 0;
  bool last_transferred_ = false;  // the last step's xfer_ holds its transfer
  // Padded window grids (see advection.hpp for the layout).
  std::vector<float> ground_, wet_, pen_, vx_, vy_, new_wet_;
  std::vector<float> pigment_, new_pigment_;  // slot-major, padded grids
  // Unpadded per-cell data of the transfer.
  std::vector<std::int32_t> brush_cell_;  // brush cell touching each window cell, or -1
  std::vector<float> brush_paint_at_;     // its paint height (0 where none touches)
  std::vector<float> brush_share_cap_;    // on_brush / (deposit_share * sharers), if binding
  std::vector<float> xfer_;               // paint height moved brush -> canvas (signed)
  std::vector<float> contact_weight_;     // how fully the head moves each cell's paint, 0..1
  std::vector<float> touch_;              // how fully its film joins the brush's, 0..1
  std::vector<float> drag_weight_;  // a blade's share of each cell's paint it carries (see step)
  std::vector<float> face_east_, face_south_;  // squeeze: signed share crossing each face
  std::vector<int> face_lo_, face_hi_;         // a long step's face range per row (squeeze_rows)
  bool faces_in_range_ = false;
  std::vector<float> xfer_ratio_;  // xfer_ / the source's paint height
  // A long step's film split runs in its sub-steps (see step): the paint each cell exchanged
  // over them all (signed, as xfer_), and the brush paint of one row as that sub-step meets it.
  std::vector<float> exchanged_;
  std::vector<float> head_level_, pen_now_;  // padded: see sub_step_penetration_rows
  bool swept_ = false;                       // this step's transfer ran in sub-steps
  std::vector<float> xfer_pigment_;          // pigment moved brush -> canvas, slot-major
  std::vector<std::int32_t> brush_share_;    // canvas cells touching each brush cell
  std::vector<int> row_contacts_;
  std::vector<int> contact_lo_, contact_hi_;  // each row's touching cells, [lo, hi)
  std::vector<int> span_lo_, span_hi_;        // and where paint can change (see step)
  std::vector<int> need_lo_, need_hi_;        // and whose drag shares a sub-step reads
  std::vector<Shift> shifts_;                 // a long step's earlier sub-steps' contact
  struct SubMove {
    double x, y, length;  // cells; the length scaled so that they add up to the step's
  };
  std::vector<SubMove> sub_moves_;  // what each sub-step moves (see step)
  std::vector<const float*> from_;  // the quantities advection moves
  std::vector<float*> to_;          // and where they go
  Advection advection_;
  // Weave heights of the window's tiles; tiles never painted are cached here, so hovering
  // costs no tile memory.
  std::vector<const float*> bases_;
  int tx0_ = 0, ty0_ = 0, tiles_across_ = 0;
  std::unordered_map<int, std::vector<float>> base_cache_;
  std::vector<int> missing_tiles_;  // the window's tiles not made yet (see scatter)
};

}  // namespace impasto::paintcore
