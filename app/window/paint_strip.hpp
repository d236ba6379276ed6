#pragma once
// Fast colour: a strip of the library's paints as chips (each drawn as its masstone looks
// under the window's light) and of the mixes loaded lately. A click loads the brush with that
// paint or mix (wiping it first when the Palette says so); Shift- or Ctrl-click adds a part of
// the paint to the Palette's mix instead. The Palette's Load brush goes through the same
// load_palette_mix, so every load joins the recent mixes.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/sim_worker.hpp"
#include "window/saved_mixes.hpp"
#include "window/strip_palette.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// The recent mixes kept: the newest first, one each.
inline constexpr std::size_t kRecentMixes = 8;

// Loads the brush with the Palette's mix (wiping first when asked and there is paint on the
// brush or queued) and remembers the mix among the recent ones. `brush_volume_mm3`: the paint
// on the brush now.
void load_palette_mix(WindowState& s, session::SimWorker& worker, double brush_volume_mm3);

// The mix remembered: moved to the front of `recent` (kept to kRecentMixes).
void remember_mix(std::vector<RecentMix>& recent, const RecentMix& mix);

// The strip, drawn in the current ImGui window, flowing within `bar_right`: the painter's
// palette of the library's paints (strip_palette.hpp: a right-click leaves a paint out, "..."
// at the end chooses them all), then the recent mixes, then the saved ones (saved_mixes.hpp:
// a chip each, drawn as the mix's masstone under the window's light; a click loads it, a
// right-click removes it, "+" saves the Palette's mix under a name). It owns the palette and
// the saved mixes (read on first use) and the saved chips' colours.
class PaintStrip {
 public:
  void draw(WindowState& s, session::SimWorker& worker, double brush_volume_mm3, float bar_right);

 private:
  void draw_paints(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                   float bar_right);
  void draw_saved(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                  float bar_right);
  void draw_palette_choice(WindowState& s, float bar_right);
  void update_saved(WindowState& s);
  // Into the painter's files; each says so when it cannot.
  void store_saved(WindowState& s);
  void store_palette(WindowState& s);

  std::optional<StripPalette> palette_;
  std::optional<std::vector<SavedMix>> mixes_;
  std::vector<std::array<float, 3>> rgb_;
  std::string light_;             // the light rgb_ was made under
  std::array<char, 128> name_{};  // the Save mix popup's field
};

// The recent row alone (PaintStrip draws it).
void draw_recent_mixes(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                       float bar_right);

}  // namespace impasto::app::window
