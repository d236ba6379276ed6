#pragma once
// The palette board in the window: its panel (the board drawn from the CPU renderer, tools
// to lay out paint and to mix, and the pick-up onto the canvas brush), fed by the mouse
// through a session::PenFeed as the canvas is.
#include <impasto/render/render_settings.hpp>
#include <impasto/render/tile_renderer.hpp>
#include <impasto/render_gl/texture.hpp>

#include <memory>
#include <string>
#include <vector>

#include "impasto/session/pen_feed.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/palette_board.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class PaletteBoardPanel {
 public:
  PaletteBoardPanel();

  PaletteBoard& board() { return board_; }
  // A board for another painting (opened, or new): shown from the next frame.
  void replace(PaletteBoard board);
  // Draws the panel inside the current ImGui window; a pick-up goes to `worker` as a wipe and
  // a load of the canvas brush (so the session records it).
  void draw(WindowState& state, session::SimWorker& worker);

 private:
  bool refresh_image(const render::RenderSettings& settings);

  enum class Tool { kLayOut, kMix };
  PaletteBoard board_;
  session::PenFeed feed_;
  Tool tool_ = Tool::kMix;
  std::unique_ptr<render::TileRenderer> renderer_;
  std::vector<std::string> rendered_slots_;
  std::string rendered_light_;
  int rendered_wavelengths_ = 0;
  bool full_render_ = true;
  render_gl::Texture texture_;
  std::vector<unsigned char> rgba_;
  std::string message_;
};

}  // namespace impasto::app::window
