#pragma once
// Fast colour: a strip of the library's paints as chips (each drawn as its masstone looks
// under the window's light) and of the mixes loaded lately. A click loads the brush with that
// paint or mix (wiping it first when the Palette says so); Shift- or Ctrl-click adds a part of
// the paint to the Palette's mix instead. The Palette's Load brush goes through the same
// load_palette_mix, so every load joins the recent mixes.
#include <vector>

#include "impasto/session/sim_worker.hpp"
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

// The strip, drawn in the current ImGui window, flowing within `bar_right`: the paints, then
// the recent mixes and the saved ones (saved_mixes.hpp; a click loads one, a right-click
// removes it, "+" saves the Palette's mix under a name).
void draw_paint_strip(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                      float bar_right);
// The recent row alone (draw_paint_strip draws it).
void draw_recent_mixes(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                       float bar_right);

}  // namespace impasto::app::window
