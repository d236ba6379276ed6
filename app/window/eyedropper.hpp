#pragma once
// The eyedropper: it picks the paint under the cursor, not a colour. A painting keeps its
// pigments, so the pick is the paint itself (paintcore::probe_paint: which pigments, in what
// shares, how thick wet and dry), its colour is rendered from that mix as the Palette panel's
// chips are, and the brush can be loaded with it the way the palette board's pick-up loads it
// (load_onto_brush). The tool is I (shortcuts.hpp) or Alt held over the canvas.
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/paint_surface.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/render_settings.hpp>

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "impasto/session/sim_worker.hpp"
#include "window/pointer_events.hpp"

namespace impasto::app::window {

// The disc the eyedropper reads, in canvas cells (a 5 x 5 cell neighbourhood, rounded).
inline constexpr double kPickRadiusCells = 2.0;

struct PickedPaint {
  std::array<double, 2> cell{};         // where it was picked (canvas cells)
  std::vector<input::PigmentPart> mix;  // by pigment name; parts are percent, largest first
  double wet_mm = 0.0, dry_mm = 0.0;    // mean heights over the disc
  bool dry = false;  // most of the visible paint there is dry (the wet paint is gone)
  // The medium to load for paint that dries as the picked paint does (paintcore::
  // loadable_medium: none where less than half of it holds a medium).
  std::optional<paintcore::Medium> medium;
  // Display RGB: the mix opaque, and as thick a layer of it as was picked over the ground.
  std::array<float, 3> masstone_rgb{0.5f, 0.5f, 0.5f}, layer_rgb{0.5f, 0.5f, 0.5f};
  bool rendered = false;
};

// The paint within `radius_cells` of (x_cells, y_cells); nullopt over bare canvas.
std::optional<PickedPaint> pick_paint(const paintcore::Painting& painting, double x_cells,
                                      double y_cells, double radius_cells = kPickRadiusCells);
// Renders the chips (session/swatch.hpp's flat layers), under `rule` (the painting's) when given.
// Throws std::runtime_error for a pigment the library does not know (a painting's carried pigment
// that was removed).
void render_picked_colours(PickedPaint& picked, const render::RenderSettings& settings,
                           const render::SpectralSampling* rule = nullptr);
// What the brush takes: the picked mix with its medium, volume_mm3 of it, in `body`.
input::LoadEvent picked_load(const PickedPaint& picked, double volume_mm3, const std::string& body);
// The Palette panel's medium for the picked paint (palette_medium.hpp): its finish (none:
// nullopt) and amount.
void set_palette_medium(const PickedPaint& picked, std::optional<paintcore::Finish>& finish,
                        float& amount);
// "matte:0.40", or "none" (the panel's line).
std::string picked_medium_text(const PickedPaint& picked);
// The canvas brush takes exactly `load`: wiped first, then loaded, both through the session
// (so a replay does the same). The palette board's pick-up and the eyedropper both use it.
void load_onto_brush(session::SimWorker& worker, input::LoadEvent load);
// The Palette panel's parts for `mix` (by the database's pigments, the largest 10); names the
// database lacks are returned.
std::vector<std::string> set_palette_mix(std::span<const input::PigmentPart> mix,
                                         std::vector<float>& mix_parts);

// What the window keeps of the eyedropper.
struct EyedropperState {
  bool tool = false;         // the eyedropper is the tool (I); B goes back to the brush
  bool load_on_pick = true;  // a pick loads the brush at once (else: the panel's button)
  std::optional<PickedPaint> picked;
  std::string message;  // why the last pick could not be used
  bool reveal = false;  // a pick was made: the panel opens to show it
};

// Takes the eyedropper's presses out of the frame's mouse events: while `picking`, a left
// press on the canvas starts a pick that follows the mouse until the button is released
// (`pick(at, released)` for each), and none of those events paints. Every other event is
// returned, in order, for the canvas's gestures.
class PickGesture {
 public:
  using PickHandler = std::function<void(const PointerEvent& at, bool released)>;
  std::vector<PointerEvent> take_picks(std::span<const PointerEvent> events, bool picking,
                                       const std::function<bool(double, double)>& canvas_at,
                                       const PickHandler& pick);
  bool held() const { return held_; }

 private:
  bool held_ = false;
};

}  // namespace impasto::app::window
