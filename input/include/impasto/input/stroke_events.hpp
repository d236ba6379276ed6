#pragma once
// The records of a painting session: pen samples and the events between them, in the order
// they happened, so that a whole session can be replayed. Files: docs/stroke-format.md.
#include <impasto/paintcore/paint_surface.hpp>
#include <impasto/paintcore/pen_sample.hpp>
#include <impasto/paintcore/step_quality.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace impasto::input {

// The version of the stroke file format this program writes, and the oldest it reads.
// Version 2 adds the `from` and `saved` records and ends every record with a newline, so a
// last line without one is a torn write.
inline constexpr int kStrokeFormatVersion = 2;
inline constexpr int kOldestStrokeFormatVersion = 1;

// One pen sample. A stroke is a maximal run of samples whose tip bit (kPenTip) is set.
struct SampleEvent {
  paintcore::PenSample sample;
  bool operator==(const SampleEvent& other) const;
};

// The canvas the session was painted on: size in cells and cells per inch.
struct CanvasEvent {
  int width_cells = 0;
  int height_cells = 0;
  double dpi = 0.0;
  bool operator==(const CanvasEvent&) const = default;
};

// Switch to a tool by name ("brush", "eraser", "knife", ...).
struct ToolEvent {
  std::string name;
  bool operator==(const ToolEvent&) const = default;
};

// An extra numeric setting of a brush head, kept in the order it was written.
struct BrushParam {
  std::string key;
  double value = 0.0;
  bool operator==(const BrushParam&) const = default;
};

// Choose a brush head (by name) with its size in mm and stiffness (0 soft .. 1 stiff).
struct BrushEvent {
  std::string head;
  double size_mm = 0.0;
  double stiffness = 0.0;
  std::vector<BrushParam> params;
  bool operator==(const BrushEvent&) const = default;
};

// One pigment of a mix and its share, in parts (only ratios matter).
struct PigmentPart {
  std::string pigment;  // as named in the pigment database, e.g. "White"
  double parts = 0.0;
  bool operator==(const PigmentPart&) const = default;
};

// Load the brush with a volume of a pigment mix.
struct LoadEvent {
  // A constructor, not an aggregate: the medium came later, and the callers that name only
  // the volume, the mix and the body need not spell it.
  LoadEvent() = default;
  LoadEvent(double volume, std::vector<PigmentPart> parts, std::string paint_body = {},
            std::string paint_medium = {})
      : volume_mm3(volume),
        mix(std::move(parts)),
        body(std::move(paint_body)),
        medium(std::move(paint_medium)) {}
  double volume_mm3 = 0.0;
  std::vector<PigmentPart> mix;
  // The paint's body (paint_body.hpp); the default body when empty.
  std::string body;
  // The paint's medium, "FINISH[:AMOUNT]" (paintcore::parse_medium); none when empty.
  std::string medium;
  bool operator==(const LoadEvent&) const = default;
};

// Wipe the brush clean.
struct WipeEvent {
  bool operator==(const WipeEvent&) const = default;
};

// Let the wet layer dry by a fraction (0 nothing .. 1 fully dry).
struct DryEvent {
  double fraction = 0.0;
  bool operator==(const DryEvent&) const = default;
};

// Coat the painting with varnish (Painting::apply_varnish): a finish, a thickness in mm
// (0 < t <= paintcore::kMaxVarnishMm), over the whole painting or the cells of `region`
// (clipped to the canvas).
struct VarnishEvent {
  paintcore::Finish finish = paintcore::Finish::satin;
  double thickness_mm = 0.0;
  std::optional<paintcore::CellRect> region;
  bool operator==(const VarnishEvent&) const = default;
};

// How finely the simulation steps the brush from here on (paintcore/step_quality.hpp). It
// does not end a stroke: the window takes faster steps mid-stroke while it is behind.
struct QualityEvent {
  paintcore::StepQuality quality = paintcore::StepQuality::balanced;
  bool operator==(const QualityEvent&) const = default;
};

struct UndoEvent {
  bool operator==(const UndoEvent&) const = default;
};

struct RedoEvent {
  bool operator==(const RedoEvent&) const = default;
};

// The painting a session started from: a new canvas (the `canvas` record gives it), or a
// painting file as it was then (path and Painting::state_hash()).
struct OriginEvent {
  bool new_canvas = true;
  std::string painting;  // when !new_canvas
  std::uint64_t state_hash = 0;
  bool operator==(const OriginEvent&) const = default;
};

// The painting was saved here (by the user, or an autosave): the file and the state it holds.
struct SavedEvent {
  std::string painting;
  std::uint64_t state_hash = 0;
  bool operator==(const SavedEvent&) const = default;
};

using StrokeEvent =
    std::variant<SampleEvent, CanvasEvent, ToolEvent, BrushEvent, LoadEvent, WipeEvent, DryEvent,
                 UndoEvent, RedoEvent, OriginEvent, SavedEvent, VarnishEvent, QualityEvent>;

// A whole stroke file: its format version and its records in order. Two files are equal
// when their versions and events are; where they were read from does not count.
struct StrokeFile {
  int version = kStrokeFormatVersion;
  std::vector<StrokeEvent> events;
  // Where the file was read from, for messages: its name, each event's line, and what the
  // reader let pass with a warning (a torn last line).
  std::string source;
  std::vector<int> lines;
  std::vector<std::string> warnings;
  bool operator==(const StrokeFile& other) const {
    return version == other.version && events == other.events;
  }
  // "FILE:LINE" of event i, or "record N" when the file was not read from text.
  std::string where(std::size_t i) const;
};

// A stroke: the index range [begin, end) of its samples in a list of pen samples.
struct StrokeSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
  bool operator==(const StrokeSpan&) const = default;
};

// The pen samples of a file, in order (other events dropped).
std::vector<paintcore::PenSample> pen_samples(const StrokeFile& file);

// The strokes in a list of samples: maximal runs with the tip bit set.
std::vector<StrokeSpan> split_strokes(const std::vector<paintcore::PenSample>& samples);

}  // namespace impasto::input
