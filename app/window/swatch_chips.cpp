#include "window/swatch_chips.hpp"

#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <chrono>
#include <exception>

namespace impasto::app::window {
namespace {

// A glaze thin enough to show a dark paint's hue over the ground (2 optical units at the
// default thickness scale).
constexpr double kGlazeChipMm = 0.01;

}  // namespace

SwatchChips::~SwatchChips() {
  if (job_.valid()) job_.wait();
}

SwatchChips::Result SwatchChips::compute(const session::SwatchStroke& stroke,
                                         const render::RenderSettings& settings, double layer_mm,
                                         const render::SpectralSampling& rule) {
  Result result;
  if (!stroke.load.mix.empty()) {
    result.swatch = make_swatch(stroke, settings, &rule);
    layer_mm = result.swatch->deposit.median_mm;
  }
  std::vector<std::vector<input::PigmentPart>> singles;
  for (const auto& pigment : data::PigmentDatabase::defaults().all())
    singles.push_back({{pigment.name, 1.0}});
  result.pigment_masstones = session::render_flat_layers(
      settings, singles, session::masstone_thickness_mm(settings), &rule);
  result.pigment_layers = session::render_flat_layers(settings, singles, layer_mm, &rule);
  result.pigment_glazes = session::render_flat_layers(settings, singles, kGlazeChipMm, &rule);
  return result;
}

void SwatchChips::update(WindowState& s, const paintcore::CanvasSpec& canvas,
                         const render::SpectralSampling& rule) {
  if (job_.valid() && job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    s.swatch_busy = false;
    try {
      const Result result = job_.get();
      if (result.swatch) {
        s.swatch_on_canvas_rgb = session::clamped(result.swatch->on_canvas);
        s.swatch_masstone_rgb = session::clamped(result.swatch->masstone);
        s.swatch_thickness_mm = result.swatch->deposit.median_mm;
      }
      s.pigment_masstone_rgb.clear();
      s.pigment_layer_rgb.clear();
      for (const session::DisplayRgb& rgb : result.pigment_masstones)
        s.pigment_masstone_rgb.push_back(session::clamped(rgb));
      for (const session::DisplayRgb& rgb : result.pigment_layers)
        s.pigment_layer_rgb.push_back(session::clamped(rgb));
      s.pigment_glaze_rgb.clear();
      for (const session::DisplayRgb& rgb : result.pigment_glazes)
        s.pigment_glaze_rgb.push_back(session::clamped(rgb));
      s.swatch_error.clear();
    } catch (const std::exception& e) {
      s.swatch_error = e.what();
    }
  }
  if (job_.valid()) return;  // one at a time; the latest settings go next
  session::SwatchStroke stroke;
  stroke.brush = brush_event(s);
  stroke.load = load_event(s);
  stroke.pressure = s.mouse_pressure;
  stroke.dpi = canvas.dpi;
  stroke.weave_seed = canvas.weave_seed;
  const bool same_rule =
      rule.wavelengths_nm == started_rule_.wavelengths_nm && rule.to_xyz == started_rule_.to_xyz;
  if (!s.mix_changed && started_ && *started_ == stroke && same_rule) return;
  s.mix_changed = false;
  started_ = stroke;
  started_rule_ = rule;
  s.swatch_busy = true;
  // Without a mix the pigment rows still show a layer as thick as the last deposit.
  const double layer_mm = s.swatch_thickness_mm > 0.0 ? s.swatch_thickness_mm : 0.1;
  job_ = std::async(std::launch::async, &SwatchChips::compute, stroke, s.settings, layer_mm, rule);
}

}  // namespace impasto::app::window
