#include "window/window_state.hpp"

#include <impasto/data/cie.hpp>
#include <impasto/paintcore/brush_head.hpp>

#include <algorithm>
#include <filesystem>

#include "window/tool_bar.hpp"

namespace impasto::app::window {

namespace {

// The heads in the brushes folder, by name.
std::vector<std::string> brush_heads() {
  std::vector<std::string> heads;
  std::error_code error;
  for (const auto& entry :
       std::filesystem::directory_iterator(paintcore::default_brushes_dir(), error)) {
    if (entry.path().extension() == ".brush") heads.push_back(entry.path().stem().string());
  }
  std::sort(heads.begin(), heads.end());
  return heads;
}

}  // namespace

WindowState initial_window_state(const PaintOptions& options) {
  WindowState state;
  state.settings.wavelengths = options.wavelengths;
  state.quality = options.quality;
  state.catch_up = options.catch_up;
  state.reference_requested = options.reference;
  state.illuminants = data::illuminant_names();
  const auto d65 = std::find(state.illuminants.begin(), state.illuminants.end(), "D65");
  state.illuminant =
      d65 == state.illuminants.end() ? 0 : static_cast<int>(d65 - state.illuminants.begin());
  state.brush_heads = brush_heads();
  reload_presets(state);
  state.recent = session::load_recent_files();
  return state;
}

}  // namespace impasto::app::window
