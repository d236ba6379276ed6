#include "impasto/session/replay.hpp"

#include <impasto/paintcore/brush_head.hpp>
#include <impasto/paintcore/step_quality.hpp>

#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <type_traits>

#include "impasto/files/memory_budget.hpp"

namespace impasto::session {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// The body a load record names (checked when the file was read), or the default.
paintcore::PaintBody load_body(const input::LoadEvent& load) {
  if (load.body.empty()) return paintcore::kDefaultPaintBody;
  if (const auto body = paintcore::paint_body_from_name(load.body)) return *body;
  throw std::runtime_error("load: unknown paint body '" + load.body.substr(0, 32) + "'");
}

std::string hex64(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

bool has_load_record(const input::StrokeFile& file) {
  for (const auto& event : file.events) {
    if (std::holds_alternative<input::LoadEvent>(event)) return true;
  }
  return false;
}

const std::vector<std::string>& demo_palette() {
  static const std::vector<std::string> palette = {
      "Blue Red Shade", "Cold Yellow", "Magenta",          "Green",
      "White",          "Red Oxide",   "Blue Green Shade", "Red"};
  return palette;
}

SessionPlayer::SessionPlayer(paintcore::Painting& painting, const ReplayOptions& options,
                             bool auto_load)
    : painting_(painting), options_(options), auto_load_(auto_load) {
  if (painting_.brush().empty()) {
    // The default head no wider than the canvas's cells allow (at 5000 dpi 6 mm is 1181 cells):
    // the recording did not ask for its size, so it is not an error in the recording.
    paintcore::BrushSettings settings = options_.default_brush;
    const double widest_mm = paintcore::kMaxBrushCells * painting_.canvas().cell_mm();
    settings.size_mm = std::min(settings.size_mm, widest_mm);
    painting_.set_brush(settings);
  }
}

void SessionPlayer::begin_auto_stroke() {
  if (painting_.brush_totals().volume > 0) painting_.wipe_brush();
  const auto& palette = demo_palette();
  const std::string& pigment = palette[palette_index_++ % palette.size()];
  double volume = options_.auto_load_mm3;
  if (volume <= 0) {
    const double width = painting_.brush().settings().size_mm;
    volume = 2.0 * width * width;  // a loaded brush: 2 mm of paint over the head's square
  }
  painting_.load_brush({{pigment, 1.0}}, volume);
}

void SessionPlayer::on_sample(const paintcore::PenSample& sample) {
  ++report_.samples;
  const bool down = sample.tip_down();
  if (down && !painting_.in_stroke()) {
    if (auto_load_) begin_auto_stroke();
    if (erasing_ && painting_.brush_totals().volume > 0) painting_.wipe_brush();
    painting_.begin_stroke();
    ++report_.strokes;
  }
  if (painting_.in_stroke()) painting_.stroke_to(sample);
  if (!down && painting_.in_stroke()) {
    painting_.end_stroke();
    // An eraser is a brush that is cleaned after each stroke: what it picked up is gone.
    if (erasing_ && painting_.brush_totals().volume > 0) painting_.wipe_brush();
  }
}

void SessionPlayer::apply(const input::StrokeEvent& event) {
  // Records other than samples end an open stroke first, as a live session would.
  if (!std::holds_alternative<input::SampleEvent>(event) &&
      !std::holds_alternative<input::QualityEvent>(event))
    finish();
  std::visit(
      Overloaded{
          [&](const input::SampleEvent& e) { on_sample(e.sample); },
          [&](const input::CanvasEvent&) {},  // consumed by replay_canvas()
          [&](const input::ToolEvent& e) {
            if (e.name == "brush") {
              erasing_ = false;
            } else if (e.name == "eraser") {
              erasing_ = true;
            } else {
              throw std::runtime_error("unknown tool '" + e.name + "' (known: brush, eraser)");
            }
          },
          [&](const input::BrushEvent& e) {
            paintcore::BrushSettings settings;
            settings.head = e.head;
            settings.size_mm = e.size_mm;
            settings.stiffness = e.stiffness;
            // The record's bristle settings replace the head file's (the reader checked their
            // ranges and warned of keys it does not know).
            const auto known = [](const input::BrushParam& param) {
              return paintcore::find_bristle_setting(param.key) != nullptr;
            };
            if (std::none_of(e.params.begin(), e.params.end(), known)) {
              painting_.set_brush(settings);
              return;
            }
            paintcore::BrushHead head = paintcore::load_named_brush_head(e.head);
            for (const input::BrushParam& param : e.params)
              if (known(param)) paintcore::find_bristle_setting(param.key)->of(head) = param.value;
            painting_.set_brush(settings, head);
          },
          [&](const input::LoadEvent& e) {
            std::vector<paintcore::PigmentMixPart> mix;
            for (const auto& part : e.mix) {
              // Known to the painting (it carries the pigment) or to the library; else throws.
              if (!painting_.pigment_records().count(part.pigment))
                data::PigmentDatabase::defaults().get(part.pigment);
              mix.push_back({part.pigment, part.parts});
            }
            painting_.load_brush(
                mix, e.volume_mm3, load_body(e),
                e.medium.empty() ? std::nullopt : std::optional(paintcore::parse_medium(e.medium)));
          },
          [&](const input::WipeEvent&) { painting_.wipe_brush(); },
          [&](const input::DryEvent& e) { painting_.dry(e.fraction); },
          [&](const input::QualityEvent& e) {
            if (!options_.quality)
              painting_.set_params(paintcore::with_step_quality(painting_.params(), e.quality));
          },
          [&](const input::VarnishEvent& e) {
            painting_.apply_varnish(e.finish, e.thickness_mm, e.region);
          },
          [&](const input::UndoEvent&) { painting_.undo(); },
          [&](const input::RedoEvent&) { painting_.redo(); },
          // Where the session began and was saved: used by rebuild_session (rebuild.hpp).
          [&](const input::OriginEvent&) {},
          [&](const input::SavedEvent&) {},
      },
      event);
}

void SessionPlayer::finish() {
  if (painting_.in_stroke()) {
    painting_.end_stroke();
    if (erasing_ && painting_.brush_totals().volume > 0) painting_.wipe_brush();
  }
}

paintcore::CanvasSpec replay_canvas(const input::StrokeFile& file, const ReplayOptions& options) {
  paintcore::CanvasSpec spec = options.default_canvas;
  for (const auto& event : file.events) {
    if (const auto* canvas = std::get_if<input::CanvasEvent>(&event)) {
      spec.width_cells = canvas->width_cells;
      spec.height_cells = canvas->height_cells;
      spec.dpi = canvas->dpi;
      break;
    }
  }
  if (options.width_cells) spec.width_cells = *options.width_cells;
  if (options.height_cells) spec.height_cells = *options.height_cells;
  if (options.dpi) spec.dpi = *options.dpi;
  paintcore::validate(spec);
  return spec;
}

paintcore::SimulationParams replay_params(const ReplayOptions& options) {
  return options.quality ? paintcore::with_step_quality(options.params, *options.quality)
                         : options.params;
}

paintcore::Painting replay(const input::StrokeFile& file, const ReplayOptions& options,
                           ReplayReport* report) {
  paintcore::Painting painting(replay_canvas(file, options), options.threads);
  painting.set_params(replay_params(options));
  SessionPlayer player(painting, options, options.auto_load && !has_load_record(file));
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < file.events.size(); ++i) {
    try {
      player.apply(file.events[i]);
    } catch (const std::exception& e) {
      throw std::runtime_error(file.where(i) + ": " + files::error_text(e));
    }
    if (options.progress) options.progress(i + 1, file.events.size());
  }
  player.finish();
  if (report) {
    *report = player.report();
    report->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return painting;
}

nlohmann::json replay_stats(const paintcore::Painting& painting, const ReplayReport& report) {
  const auto canvas = painting.canvas_totals();
  const auto brush = painting.brush_totals();
  const auto loaded = painting.loaded_totals();
  const auto wiped = painting.wiped_totals();
  const auto thickness = painting.paint_thickness();
  auto slot_value = [](const paintcore::PaintTotals& totals, std::size_t slot) {
    return slot < totals.pigment.size() ? totals.pigment[slot] : 0.0;
  };
  nlohmann::json pigments = nlohmann::json::array();
  const auto& slots = painting.pigment_slots();
  for (std::size_t s = 0; s < slots.size(); ++s) {
    pigments.push_back({{"slot", s},
                        {"pigment", slots[s]},
                        {"canvas", slot_value(canvas, s)},
                        {"brush", slot_value(brush, s)},
                        {"loaded", slot_value(loaded, s)},
                        {"wiped", slot_value(wiped, s)}});
  }
  const auto& spec = painting.canvas().spec();
  return {
      {"canvas",
       {{"width_cells", spec.width_cells}, {"height_cells", spec.height_cells}, {"dpi", spec.dpi}}},
      {"canvas_volume", canvas.volume},
      {"brush_volume", brush.volume},
      {"loaded_volume", loaded.volume},
      {"wiped_volume", wiped.volume},
      {"pigment_amounts", pigments},
      {"deposited_share", loaded.volume > 0.0 ? canvas.volume / loaded.volume : 0.0},
      {"thickness_mm",
       {{"painted_cells", thickness.painted_cells},
        {"median", thickness.median_mm},
        {"p90", thickness.p90_mm},
        {"p99", thickness.p99_mm},
        {"max", thickness.max_mm}}},
      {"samples", report.samples},
      {"strokes", report.strokes},
      {"steps", painting.steps()},
      {"cells_updated", painting.cells_updated()},
      {"seconds", report.seconds},
      {"dry_layers", painting.canvas().dry_layers().size()},
      {"allocated_tiles", painting.canvas().allocated_tiles()},
      {"memory_bytes", painting.memory_bytes()},
      {"nonfinite", painting.nonfinite_count()},
      {"state_hash", hex64(painting.state_hash())}};
}

}  // namespace impasto::session
