#pragma once
// What `impasto paint` was asked to do.
#include <impasto/paintcore/canvas.hpp>
#include <impasto/paintcore/step_quality.hpp>
#include <impasto/render/render_settings.hpp>

#include <filesystem>
#include <optional>

namespace impasto::app::window {

struct PaintOptions {
  std::optional<std::filesystem::path> painting;    // open this .impasto file
  std::optional<std::filesystem::path> replay;      // stroke file replayed at start
  std::optional<std::filesystem::path> reference;   // a reference image shown at start
  std::optional<std::filesystem::path> screenshot;  // PNG of the whole window once replayed
  std::optional<std::filesystem::path> record;      // session stroke file (default: beside)
  bool no_record = false;
  bool exit_after = false;  // quit once the replay and screenshot are done
  int window_width = 1400;
  int window_height = 900;
  paintcore::CanvasSpec new_canvas{1024, 768, 150.0, 1};  // when no painting is opened
  int wavelengths = render::RenderSettings{}.wavelengths;
  // How finely the simulation steps the brush, and whether it takes fast steps while it is
  // behind the pen (the View panel's Quality).
  paintcore::StepQuality quality = paintcore::StepQuality::balanced;
  bool catch_up = true;
  // An autosave to the recovery folder at least this often while painting (and whenever the
  // pen rests a few seconds).
  double autosave_seconds = 120.0;
};

// Opens the window and runs until it is closed. Throws std::runtime_error when no window
// can be made (no display) or a file cannot be read.
void run_paint_window(const PaintOptions& options);

}  // namespace impasto::app::window
