#pragma once
// The state behind a Painting (shared by painting.cpp and painting_file.cpp).
#include <tbb/task_arena.h>

#include <array>
#include <memory>
#include <optional>

#include "impasto/paintcore/brush_pose.hpp"
#include "impasto/paintcore/painting.hpp"
#include "ledger.hpp"
#include "painting_surface.hpp"
#include "stepper.hpp"
#include "stroke_path.hpp"
#include "undo_history.hpp"

namespace impasto::paintcore {

inline constexpr std::size_t kDefaultSavedHistoryBytes = std::size_t{64} << 20;

struct Painting::Impl {
  Impl(CanvasSpec spec, int thread_count)
      : canvas(spec),
        threads(thread_count > 0 ? thread_count : tbb::this_task_arena::max_concurrency()),
        arena(threads) {}

  // A painting of this one's slots, pigment records and parameters on an empty canvas of
  // `spec` (the brush, ledger, history and cracks are not carried): what the finer canvas of
  // an export and the coarser one of a thumbnail start from.
  std::unique_ptr<Impl> resampled(CanvasSpec spec) const {
    auto copy = std::make_unique<Impl>(spec, threads);
    copy->slots = slots;
    copy->pigment_records = pigment_records;
    copy->params = params;
    return copy;
  }

  // Replaces this painting's subscribers by `others`, each seeing every tile changed.
  void take_subscribers(std::vector<ChangedCells> others);

  Canvas canvas;
  std::vector<ChangedCells> subscribers;  // by ChangeSubscriber::id: what each has not taken
  int threads;
  tbb::task_arena arena;
  std::vector<std::string> slots;
  std::map<std::string, std::string> pigment_records;  // name -> record (painting.hpp)
  SimulationParams params;
  Brush brush;
  Ledger ledger;
  UndoHistory history;
  std::size_t saved_history_bytes = kDefaultSavedHistoryBytes;  // painting.hpp
  std::string load_warning;  // what load() dropped (a damaged history section)
  Stepper stepper;
  std::uint64_t steps = 0;
  std::uint64_t cells_updated = 0;
  // The stroke in progress.
  bool in_stroke = false;
  bool stroke_touched = false;
  std::optional<BrushPose> last_pose;
  std::optional<BrushPose> pose_before_last;  // for the curve's tangent (stroke_path.hpp)
  double last_time_s = 0.0;
  // A brush that follows the hand: its heading when the pen reports no twist.
  bool stroke_has_twist = false;
  std::optional<double> heading_rad;
  bool heading_settled = false;                        // it now trails the hand
  std::optional<std::array<double, 2>> stroke_origin;  // where the stroke began (cells)
  // The brush steps by distance along its path, not once a sample: where its last step ended
  // and the path and time since then, which the next sample's steps (or the stroke's end)
  // carry on from. So how often the pen was sampled leaves no trace in the paint.
  std::optional<std::array<double, 2>> step_from;    // cells
  std::optional<std::array<double, 2>> step_origin;  // where the steps started (cells)
  // (And the change of depth: a pen easing off steps as often as the contact's edge needs.)
  double pending_cells = 0.0, pending_seconds = 0.0, pending_depth_mm = 0.0;
  void clear_pending() { pending_cells = pending_seconds = pending_depth_mm = 0.0; }
  std::optional<BrushPose> last_contact;  // where the brush last touched paint: it lifts there
  std::array<double, 2> last_move{};      // the last step's move (cells)
  double last_move_seconds = 0.0;         // and how long it took
  std::vector<int> stroke_tiles;          // tiles the stroke changed: where its paint levels
  StrokeMedia stroke_media;               // the media the stroke's brush laid, step by step

  // A reframe, or its undo or redo, changes the cloth a tile index stands for: the
  // stepper's cached weave of untouched tiles must go.
  void forget_weave_cache_if_reframed(const CanvasSpec& before) {
    const CanvasSpec& now = canvas.spec();
    if (before.width_cells != now.width_cells || before.height_cells != now.height_cells ||
        before.weave_origin_x_cells != now.weave_origin_x_cells ||
        before.weave_origin_y_cells != now.weave_origin_y_cells)
      stepper = Stepper();
  }

  // One simulation step to `pose`, moved (move_x, move_y) cells from the last step's end in
  // `seconds`: turns a head that follows the hand, then steps and keeps the stroke's books.
  void take_step(BrushPose pose, double move_x, double move_y, double seconds, bool follows,
                 bool lifting = false);
  // Where a long step may end: a whole number of cells from where the steps started (see
  // stroke_to); any point for a brush that steps a cell at a time.
  std::array<double, 2> step_end(std::array<double, 2> at) const;
  // The brush leaves the canvas as a brush does: from its last contact it goes on along its
  // travel, the pressure easing off, its tips last; see end_stroke.
  void lift_brush();

  // What a stroke's steps call before they first change a tile: keep it for undo, and note
  // it as the stroke's.
  void before_stroke_tile_change(int index) {
    history.before_tile_change(index, canvas.tile(index));
    stroke_tiles.push_back(index);
  }
};

}  // namespace impasto::paintcore
