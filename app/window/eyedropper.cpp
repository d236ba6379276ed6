#include "window/eyedropper.hpp"

#include <impasto/data/pigments.hpp>
#include <impasto/paintcore/paint_probe.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "impasto/session/swatch.hpp"

namespace impasto::app::window {
namespace {

// The Palette panel's sliders run from 0 to this many parts.
constexpr float kPaletteMaxParts = 10.0f;

}  // namespace

std::optional<PickedPaint> pick_paint(const paintcore::Painting& painting, double x_cells,
                                      double y_cells, double radius_cells) {
  const paintcore::PaintProbe probe =
      paintcore::probe_paint(painting, x_cells, y_cells, radius_cells);
  if (probe.bare()) return std::nullopt;
  PickedPaint picked;
  picked.cell = {x_cells, y_cells};
  picked.wet_mm = probe.wet_mm;
  picked.dry_mm = probe.dry_mm;
  picked.dry = probe.dry_cells > probe.wet_cells;
  picked.medium = paintcore::loadable_medium(probe.medium);
  // To the Palette slider's 2 decimals, as its own loads are (window_state.hpp, load_event).
  if (picked.medium) picked.medium->amount = std::round(100.0 * picked.medium->amount) / 100.0;
  const std::vector<double> shares = probe.shares();
  const auto& slots = painting.pigment_slots();
  for (std::size_t s = 0; s < shares.size() && s < slots.size(); ++s)
    if (shares[s] > 0.0) picked.mix.push_back({slots[s], 100.0 * shares[s]});
  if (picked.mix.empty()) return std::nullopt;
  std::stable_sort(picked.mix.begin(), picked.mix.end(),
                   [](const auto& a, const auto& b) { return a.parts > b.parts; });
  return picked;
}

void render_picked_colours(PickedPaint& picked, const render::RenderSettings& settings,
                           const render::SpectralSampling* rule) {
  const std::vector<input::PigmentPart>& mix = picked.mix;
  // The layer: the visible paint's thickness, wet where it is wet, else the dry paint's.
  const double layer_mm = std::max(picked.dry ? picked.dry_mm : picked.wet_mm, 1e-3);
  picked.masstone_rgb =
      session::clamped(session::render_flat_layers(settings, std::span(&mix, 1),
                                                   session::masstone_thickness_mm(settings), rule)
                           .front());
  picked.layer_rgb = session::clamped(
      session::render_flat_layers(settings, std::span(&mix, 1), layer_mm, rule).front());
  picked.rendered = true;
}

input::LoadEvent picked_load(const PickedPaint& picked, double volume_mm3,
                             const std::string& body) {
  input::LoadEvent load;
  load.volume_mm3 = volume_mm3;
  load.mix = picked.mix;
  load.body = body;
  if (picked.medium) load.medium = paintcore::medium_spelling(*picked.medium);
  return load;
}

void set_palette_medium(const PickedPaint& picked, std::optional<paintcore::Finish>& finish,
                        float& amount) {
  finish.reset();
  if (!picked.medium) return;
  finish = picked.medium->finish;
  amount = static_cast<float>(picked.medium->amount);
}

std::string picked_medium_text(const PickedPaint& picked) {
  if (!picked.medium) return "none";
  char amount[16];
  std::snprintf(amount, sizeof amount, ":%.2f", picked.medium->amount);
  return std::string(paintcore::finish_name(picked.medium->finish)) + amount;
}

void load_onto_brush(session::SimWorker& worker, input::LoadEvent load) {
  worker.submit(input::WipeEvent{});
  worker.submit(std::move(load));
}

std::vector<std::string> set_palette_mix(std::span<const input::PigmentPart> mix,
                                         std::vector<float>& mix_parts) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  mix_parts.assign(pigments.size(), 0.0f);
  double largest = 0.0;
  for (const auto& part : mix) largest = std::max(largest, part.parts);
  std::vector<std::string> unknown;
  for (const auto& part : mix) {
    const auto found = std::find_if(pigments.begin(), pigments.end(),
                                    [&](const auto& p) { return p.name == part.pigment; });
    if (found == pigments.end()) {
      unknown.push_back(part.pigment);
      continue;
    }
    // To the slider's tenths; a trace too small to show stays out of the palette's mix.
    const float parts =
        static_cast<float>(std::round(10.0 * kPaletteMaxParts * part.parts / largest) / 10.0);
    mix_parts[static_cast<std::size_t>(found - pigments.begin())] = parts;
  }
  return unknown;
}

std::vector<PointerEvent> PickGesture::take_picks(
    std::span<const PointerEvent> events, bool picking,
    const std::function<bool(double, double)>& canvas_at, const PickHandler& pick) {
  std::vector<PointerEvent> rest;
  for (const PointerEvent& event : events) {
    if (held_) {
      if (event.action == PointerAction::kMove) {
        pick(event, false);
        continue;
      }
      if (event.action == PointerAction::kRelease && event.button == kLeftButton) {
        held_ = false;
        pick(event, true);
        continue;
      }
    } else if (picking && event.action == PointerAction::kPress && event.button == kLeftButton &&
               (!canvas_at || canvas_at(event.x, event.y))) {
      held_ = true;
      pick(event, false);
      continue;
    }
    rest.push_back(event);
  }
  return rest;
}

}  // namespace impasto::app::window
