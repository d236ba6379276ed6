#pragma once
// Replaying a recorded painting session (a stroke file) onto a painting: the same path a
// live session takes, so a replay reproduces the painting bit-exactly.
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/paintcore/step_quality.hpp>
#include <impasto/util/progress.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// Only declared here: the full header costs every includer a few seconds to compile.
#include <nlohmann/json_fwd.hpp>

namespace impasto::session {

struct ReplayOptions {
  // Canvas used when the file names none (a `canvas` record) and none is forced.
  paintcore::CanvasSpec default_canvas{1024, 768, 150.0, 1};
  // Overrides the file's canvas record, field by field, when set.
  std::optional<int> width_cells, height_cells;
  std::optional<double> dpi;
  int threads = 0;                     // 0: all cores
  paintcore::SimulationParams params;  // the paint model's constants
  // Steps every stroke at this quality (paintcore/step_quality.hpp), the recording's `quality`
  // records skipped: a session painted fast while the window caught up, replayed exact.
  std::optional<paintcore::StepQuality> quality;
  // Recordings from other programs carry no brush or paint: give every stroke a clean brush
  // loaded from demo_palette() in turn. Only used when the file has no load record.
  bool auto_load = true;
  paintcore::BrushSettings default_brush{"round", 6.0, 0.5};
  double auto_load_mm3 = 0.0;  // 0: a loaded brush, 2 mm of paint over the head's square
  // Hears of the records applied so far, of the file's all (the command line's progress).
  util::ProgressCallback progress;
};

// What a replay did, beside the painting itself.
struct ReplayReport {
  std::uint64_t samples = 0;
  std::uint64_t strokes = 0;
  double seconds = 0.0;  // wall time of the simulation
};

// Whether the file loads the brush anywhere (if not, a replay auto-loads it per stroke).
bool has_load_record(const input::StrokeFile& file);

// Pigments the auto-loaded brush cycles through, one per stroke.
const std::vector<std::string>& demo_palette();

// Applies every record of `file` in order. Throws std::runtime_error naming the record
// (its index) when a record cannot be applied; the painting keeps what came before it.
class SessionPlayer {
 public:
  SessionPlayer(paintcore::Painting& painting, const ReplayOptions& options, bool auto_load);

  void apply(const input::StrokeEvent& event);
  void finish();  // ends an open stroke
  const ReplayReport& report() const { return report_; }

 private:
  void on_sample(const paintcore::PenSample& sample);
  void begin_auto_stroke();

  paintcore::Painting& painting_;
  const ReplayOptions& options_;
  bool auto_load_;
  bool erasing_ = false;
  std::size_t palette_index_ = 0;
  ReplayReport report_;
};

// The paint model a replay starts with: options.params, at options.quality's long steps when
// one is set.
paintcore::SimulationParams replay_params(const ReplayOptions& options);
// The canvas a replay of `file` paints on: the file's canvas record, overridden by options.
paintcore::CanvasSpec replay_canvas(const input::StrokeFile& file, const ReplayOptions& options);

// Replays a whole stroke file onto a new painting.
paintcore::Painting replay(const input::StrokeFile& file, const ReplayOptions& options,
                           ReplayReport* report = nullptr);

// The statistics of `impasto replay --stats` (docs/replay.md lists the fields).
nlohmann::json replay_stats(const paintcore::Painting& painting, const ReplayReport& report);

}  // namespace impasto::session
