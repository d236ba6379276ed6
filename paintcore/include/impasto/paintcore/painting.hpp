#pragma once
// A painting: the canvas (wet layer + dry layers), the brush, the pigment slot table, the
// load/wipe ledger and the undo history, driven by pen samples. The public face of paintcore.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/paintcore/pen_sample.hpp"
#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::paintcore {

struct CanvasFrame;  // canvas_reframe.hpp

struct PigmentMixPart {
  std::string pigment;  // by name; a slot is found or allocated for it
  double parts = 0;     // relative amount (any positive scale)
};

// Paint volumes in mm^3: the total, and per pigment slot.
struct PaintTotals {
  double volume = 0;
  std::vector<double> pigment;  // indexed by slot
};

// How thick the paint stands (wet + dry above the ground) over the painted cells.
struct PaintThickness {
  std::size_t painted_cells = 0;  // cells holding more than the threshold
  double median_mm = 0, p90_mm = 0, p99_mm = 0, max_mm = 0;
};

class Painting {
 public:
  explicit Painting(CanvasSpec spec, int threads = 0);  // threads 0: all cores
  ~Painting();
  Painting(Painting&&) noexcept;
  Painting& operator=(Painting&&) noexcept;

  int threads() const;

  // Pigment slots: slot index -> pigment name (paintcore does not interpret names).
  int slot_for(const std::string& pigment);  // finds or allocates; throws beyond 16 slots
  const std::vector<std::string>& pigment_slots() const;
  int slot_count() const { return static_cast<int>(pigment_slots().size()); }

  // The pigments' own data, carried so the painting renders the same without the library or
  // after it changes (docs/painting-format.md, version 4): name -> record (a pigment file's
  // text with its flake data, render/pigment_records.hpp; paintcore keeps the bytes). A slot
  // takes its records from the record source when it is allocated; save() adds any missing.
  const std::map<std::string, std::string>& pigment_records() const;
  void set_pigment_record(const std::string& name, std::string record);
  // Records to carry for a pigment: itself and what it renders with (the ground's white).
  using PigmentRecordSource =
      std::function<std::map<std::string, std::string>(const std::string& pigment)>;
  // Process-wide, set once before painting (render::install_pigment_records); none: no records.
  static void set_pigment_record_source(PigmentRecordSource source);
  static const PigmentRecordSource& pigment_record_source();

  void set_params(const SimulationParams& params);  // validated
  const SimulationParams& params() const;

  // Brush. set_brush loads head `settings.head` from the brushes folder (default_brushes_dir())
  // and keeps the brush's paint, resampled onto the new head's grid (resample_brush_paint);
  // undo restores the old brush with its paint.
  void set_brush(const BrushSettings& settings);
  void set_brush(const BrushSettings& settings, const std::filesystem::path& brushes_dir);
  void set_brush(const BrushSettings& settings, const BrushHead& head);
  const Brush& brush() const;
  // Adds volume_mm3 of paint, mixed by parts, spread evenly over the head's cells; the paint
  // on the brush takes the given body (paint_body.hpp). A medium (paint_surface.hpp) mixes
  // with the medium of the paint already on the brush by volume; none: paint without one
  // (the render settings' medium decides its finish, as before media were part of paint).
  void load_brush(const std::vector<PigmentMixPart>& mix, double volume_mm3,
                  PaintBody body = kDefaultPaintBody, std::optional<Medium> medium = std::nullopt);
  // Removes all paint from the brush; returns what was removed.
  PaintTotals wipe_brush();

  // Strokes: samples in canvas mm. Each segment between samples is cut into steps of at most
  // one cell (CFL), with the pose interpolated. Throws on NaN/Inf samples (nothing changes).
  void begin_stroke();
  void stroke_to(const PenSample& sample);
  void end_stroke();
  bool in_stroke() const;

  // Dries the bottom `fraction` (0..1) of the wet layer into a new dry layer, and the same
  // fraction of what is still wet of the varnish.
  void dry(double fraction);

  // A coat of varnish (paint_surface.hpp) of `finish`, thickness_mm [kMinVarnishMm, kMaxVarnishMm]
  // thick, over the cells of `region` (clipped to the canvas; none: the whole painting), as one
  // undoable step. It goes on wet (glossy) and dries with dry(); its finish replaces an
  // older coat's, the thicknesses add. Throws, changing nothing, on a bad finish, thickness
  // or a region outside the canvas.
  void apply_varnish(Finish finish, double thickness_mm,
                     std::optional<CellRect> region = std::nullopt);

  // Cracks of the dry paint and the ground (crack_layer.hpp). set_cracks replaces them all
  // after checking every record (validate_cracks) and marks the tiles whose cracks changed
  // dirty; tiles left without a crack are dropped. Cracks are not part of the undo history.
  void set_cracks(CrackLayer cracks);
  const CrackLayer& cracks() const { return canvas().cracks(); }

  // The canvas's size (canvas_reframe.hpp): a crop, or a resize around an anchor, as one
  // undoable operation. Paint outside the new frame is cut away: returned (mm^3) and booked
  // as wiped, so the ledger still balances. Throws, changing nothing, on an invalid frame.
  PaintTotals reframe_canvas(const CanvasFrame& frame);

  // The painting on a canvas `scale` (1..16) times finer (dpi x scale), for export at a larger
  // size: heights and pigment amounts interpolated between cells by Catmull-Rom, clamped at
  // zero, so that its render shades a smooth relief. Slots, records and parameters are kept;
  // the brush, ledger, history and cracks are not. Throws when the canvas would be too large.
  Painting refined(int scale) const;
  // The painting's canvas in `frame` (canvas_reframe.hpp; a crop, usually), as a new painting:
  // paint, dry layers and the weave's origin moved cell for cell, slots, records and
  // parameters kept; the brush, ledger, history and cracks are not (what a render of a band
  // of a large export needs; reframe_canvas is the undoable edit). Throws on an invalid frame.
  Painting cropped(const CanvasFrame& frame) const;
  // The painting on a canvas `factor` times coarser (dpi / factor, flat cloth), for a small
  // picture of it: each cell the mean of the factor x factor block it covers (heights and
  // pigment amounts; a block's medium and varnish from its centre cell). Slots, records and
  // parameters are kept; the brush, ledger, history and cracks are not. Throws when the dpi
  // would fall under 1.
  Painting coarsened(int factor) const;

  // Undo/redo of whole operations (stroke, dry, load, wipe, brush change, reframe).
  bool undo();
  bool redo();
  void set_undo_budget_bytes(std::size_t bytes);  // oldest steps go first; never the last
  std::size_t undo_depth() const;
  std::size_t redo_depth() const;
  std::size_t undo_bytes() const;

  // Inspection. Totals are in mm^3, summed in double in a fixed order.
  PaintTotals canvas_totals() const;  // wet + all dry layers
  PaintTotals wet_totals() const;
  PaintTotals dry_totals() const;
  PaintTotals brush_totals() const;
  PaintTotals loaded_totals() const;  // put on the brush by load_brush
  PaintTotals wiped_totals() const;   // taken off by wipe_brush (and brush changes)
  // Thickness percentiles over the cells holding more than painted_above_mm of paint.
  PaintThickness paint_thickness(double painted_above_mm = 1e-3) const;
  std::uint64_t state_hash() const;  // canvas, dry layers, brush, ledger, slots, params
  std::size_t nonfinite_count() const;
  std::uint64_t steps() const;          // simulation steps that touched paint
  std::uint64_t cells_updated() const;  // window cells processed by those steps
  std::size_t memory_bytes() const;     // canvas, dry layers, brush and undo history
  const Canvas& canvas() const;

  // What changed, for each consumer of the canvas (a view's copy on the GPU, a renderer's
  // image): a consumer subscribes once, then takes the tiles changed since its previous take
  // (by strokes, drying, undo, redo, edits), each with the box of its cells that changed, in
  // ascending order. Consumers never take from one another. A new subscriber, and each
  // subscriber when another painting is moved into this one, starts with every tile changed.
  struct ChangeSubscriber {
    int id = -1;
  };
  ChangeSubscriber subscribe_changes();
  std::vector<DirtyTile> take_changes(ChangeSubscriber subscriber);

  // The native .impasto file (docs/painting-format.md). save() writes atomically.
  // The file keeps the newest undo and redo steps up to saved_history_bytes (default 64 MB,
  // oldest dropped first; 0: none), so undo goes on after reopening. A damaged history
  // section is dropped on load and said in load_warning(); the painting itself still loads.
  void set_saved_history_bytes(std::size_t bytes);
  std::size_t saved_history_bytes() const;
  const std::string& load_warning() const;
  void save(const std::filesystem::path& file) const;
  // with_history false: the undo history section is not read (a render or a thumbnail needs
  // none; it is the larger part of many files).
  static Painting load(const std::filesystem::path& file, int threads = 0,
                       bool with_history = true);

 private:
  struct Impl;
  explicit Painting(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  friend struct PaintingFile;
};

}  // namespace impasto::paintcore
