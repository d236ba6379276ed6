#pragma once
// The Dear ImGui panels of the painting window: menu bar (file), palette, brush, light,
// layers, history and the status bar. They change WindowState and submit session events;
// they never touch the painting directly.
#include <impasto/paintcore/brush_head.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "impasto/session/sim_worker.hpp"
#include "window/colour_target.hpp"
#include "window/palette_board_panel.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// The painting as the panels see it this frame (copied under the painting's lock).
struct PaintingSnapshot {
  int width_cells = 0, height_cells = 0;
  double dpi = 0.0;
  std::size_t undo_depth = 0, redo_depth = 0, dry_layers = 0;
  std::vector<std::string> slots;
  double brush_volume_mm3 = 0.0;
  paintcore::BrushHead brush_head;  // the head and its grid width, for the brush outline
  int brush_cells = 0;
};

// File operations, carried out by the window (they replace or write the painting).
struct FileActions {
  std::function<void()> new_painting;  // uses state.new_*
  std::function<void(const std::filesystem::path&)> open;
  // false: not saved (said why, or the file changed on disk since this window read or wrote
  // it: state.ask_changed_on_disk, and the window asks).
  std::function<bool(const std::filesystem::path&)> save;
  // Saves whatever is on disk: the user chose to replace it (the dialog or the prompt asked).
  std::function<bool(const std::filesystem::path&)> save_over;
  std::function<void(const std::filesystem::path&)> export_image;  // .png or .exr
};

struct PanelContext {
  WindowState& state;
  session::SimWorker& worker;
  const PaintingSnapshot& painting;
  const render::SpectralPalette& palette;  // for the light's nodes
  const FileActions& files;
  PaletteBoardPanel& board;
  ColourTarget& colour_target;
};

void draw_panels(PanelContext& context);

}  // namespace impasto::app::window
