#pragma once
// What the painting window's panels show and change, shared by the frame loop
// (paint_window.cpp) and the panels (panels.cpp).
#include <impasto/data/pigments.hpp>
#include <impasto/input/hid_device.hpp>
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/brush.hpp>
#include <impasto/paintcore/paint_body.hpp>
#include <impasto/paintcore/paint_surface.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render_gl/canvas_view.hpp>
#include <impasto/render_gl/gpu_view_options.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/disk_stamp.hpp"
#include "impasto/session/recent_files.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/brush_presets.hpp"
#include "window/canvas_size_choice.hpp"
#include "window/eyedropper.hpp"
#include "window/file_browser.hpp"
#include "window/notifications.hpp"
#include "window/paint_options.hpp"
#include "window/shortcuts.hpp"
#include "window/tablet_input.hpp"

namespace impasto::app::window {

// An action that discards the painting, held while the unsaved-changes prompt is open.
enum class PendingAction { kNone, kNew, kOpen, kOpenRecent, kQuit };

// The light of a fresh window: 30° above the canvas, as galleries hang their lights (the
// "30° rule"), where `impasto render` keeps 60°: low enough that a first stroke of heavy paint
// shows its ridges, furrows and cast shadow (docs/window.md, "The first stroke").
inline constexpr double kWindowLightElevationDeg = 30.0;
inline render::RenderSettings window_render_settings() {
  render::RenderSettings settings;
  settings.light_elevation_deg = kWindowLightElevationDeg;
  return settings;
}

// A mix loaded onto the brush: its parts per pigment of the database and how it looked on
// the canvas then (the swatch), for the strip of recent mixes.
struct RecentMix {
  std::vector<float> parts;
  std::array<float, 3> rgb{0.5f, 0.5f, 0.5f};
};

struct WindowState {
  // --- look (shared with the CPU renderer's settings) ---
  render::RenderSettings settings = window_render_settings();
  render_gl::GpuViewOptions view_options;
  bool settings_changed = true;  // palette and dry bake must be rebuilt
  bool use_blackbody = false;
  int illuminant = 0;  // index into illuminants
  float kelvin = 5600.0f;
  std::vector<std::string> illuminants;

  // --- paint on the brush ---
  std::vector<float> mix_parts;         // per pigment of the database
  std::vector<RecentMix> recent_mixes;  // loaded lately, newest first (paint_strip.hpp)
  // Enough heavy paint for the default 6 mm round to lay a stroke about half a millimetre
  // thick and a few centimetres long (6 × 40 × 0.5 mm³), as a loaded brush does.
  float load_volume_mm3 = 120.0f;
  std::string paint_body{paintcore::body_info(paintcore::kDefaultPaintBody).name};
  bool wipe_before_load = true;  // "wipe first": Load sends a wipe, then the load
  // The medium the paint is mixed with (none: the Surface panel's medium decides, as for
  // paintings made before media) and its amount, 0 (tube paint) to 1 (the medium's finish).
  std::optional<paintcore::Finish> paint_medium;
  float paint_medium_amount = 1.0f;
  // The swatch (session/swatch.hpp), display RGB: the standard stroke with this brush and
  // load as rendered, the mix's masstone, and the stroke's median wet thickness.
  std::array<float, 3> swatch_on_canvas_rgb{0.5f, 0.5f, 0.5f};
  std::array<float, 3> swatch_masstone_rgb{0.5f, 0.5f, 0.5f};
  double swatch_thickness_mm = 0.0;  // 0: no swatch yet
  bool swatch_busy = false;          // being painted off the UI thread
  std::string swatch_error;
  // Per pigment of the database: its masstone and a layer as thick as the swatch's deposit.
  std::vector<std::array<float, 3>> pigment_masstone_rgb, pigment_layer_rgb;
  std::vector<std::array<float, 3>> pigment_glaze_rgb;  // 0.01 mm over the ground: the hue
  bool mix_changed = true;  // the light changed: the swatch is redone even for the same stroke

  // --- brush and pen ---
  paintcore::BrushSettings brush{"round", 6.0, 0.5};
  std::vector<std::string> brush_heads;
  bool pressure_from_speed = false;
  float mouse_pressure = 0.6f;

  // --- simulation (paintcore/step_quality.hpp) ---
  paintcore::StepQuality quality = paintcore::StepQuality::balanced;
  bool catch_up = true;      // fast steps while the simulation is behind the pen
  bool catching_up = false;  // taking them now (the status bar says so)

  // --- tools, brush presets, commands (eyedropper.hpp, brush_presets.hpp, shortcuts.hpp) ---
  EyedropperState eyedropper;
  PresetLibrary presets;
  bool open_save_preset = false;  // open the "Save brush preset" prompt
  std::string preset_name_input;
  // Asked for by keys, menu items and the close button, not yet carried out (shortcuts.hpp):
  // the one queue of requests.
  std::vector<Command> commands;
  bool show_shortcuts = false, show_about = false;

  // --- tablets (the mouse paints when none is in use) ---
  TabletSettings tablet;
  std::vector<input::hid::ConnectedTablet> tablets;  // refreshed by the frame loop
  std::uint64_t tablet_samples = 0;                  // fed to the canvas this session
  std::string tablet_error;                          // why the last sample could not be mapped

  // --- layers ---
  float dry_fraction = 1.0f;
  std::vector<bool> hidden_dry_layers;
  bool visibility_changed = false;

  // --- view ---
  render_gl::CanvasView view;
  bool fit_requested = true;

  // --- files ---
  std::optional<std::filesystem::path> file;     // the painting's file, once saved or opened
  std::optional<session::DiskStamp> file_stamp;  // that file as this window last read or wrote it
  bool ask_changed_on_disk = false;              // Save found `file` changed since: ask what to do
  std::vector<std::filesystem::path> recent;
  PendingAction pending = PendingAction::kNone;
  bool pending_confirmed = false;    // no unsaved changes, or the user said to go ahead
  bool ask_unsaved = false;          // open the Save / Discard / Cancel prompt for `pending`
  bool continue_after_save = false;  // that prompt's Save went to Save as: go on once saved
  bool timelapse_requested = false;  // File > Export time-lapse...: open its dialog
  std::optional<std::filesystem::path> reference_requested;  // View > Reference image...
  std::filesystem::path pending_path;
  FileBrowser file_browser{session::window_config_folder().empty()
                               ? std::filesystem::path()
                               : session::window_config_folder() / "folders.txt"};
  // The New painting dialog: the size in mm (shown in new_unit), a standard size or custom
  // (-1), its orientation; new_width/new_height are the cells it makes at new_dpi.
  int new_width = 1024, new_height = 768;
  float new_dpi = 150.0f;
  double new_width_mm = 1024 * 25.4 / 150.0, new_height_mm = 768 * 25.4 / 150.0;
  SizeUnit new_unit = SizeUnit::mm;
  int new_standard = -1;
  bool new_landscape = true;
  // What the window has to say (errors, warnings, results): shown as notifications.
  Notifications notifications;

  // --- status ---
  double frame_ms = 0.0;
  double upload_ms = 0.0;
  long long tiles_uploaded = 0;  // since the window opened
  long long pixels_shaded = 0;   // by the K-M pass since the window opened (the rest cached)
  // Pen event to the swap showing it, over the last 100 samples (< 0: none yet), and how far
  // the screen is behind the pen now (the oldest sample not yet shown; 0: none waits).
  double input_latency_ms = -1.0, input_latency_p95_ms = -1.0, input_behind_ms = 0.0;
  std::array<double, 2> cursor_cell{-1, -1};
  bool quit = false;
  // Textures a panel re-uploaded this frame: ImGui draws them the same, but their pixels
  // changed and must be presented (UiDamage::texture_changed).
  std::vector<std::uintptr_t> ui_textures_changed;
};

// The session events the panels send for the brush and the load, built in one place so the
// swatch paints with exactly what the painting gets.
inline input::BrushEvent brush_event(const WindowState& s) {
  input::BrushEvent event;
  event.head = s.brush.head;
  event.size_mm = s.brush.size_mm;
  event.stiffness = s.brush.stiffness;
  return event;
}
inline input::LoadEvent load_event(const WindowState& s) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  input::LoadEvent event;
  event.volume_mm3 = s.load_volume_mm3;
  event.body = s.paint_body;
  if (s.paint_medium)
    event.medium = paintcore::medium_spelling(  // to the slider's 2 decimals: "matte:0.3"
        {*s.paint_medium, std::round(100.0 * s.paint_medium_amount) / 100.0});
  for (std::size_t i = 0; i < pigments.size() && i < s.mix_parts.size(); ++i) {
    if (s.mix_parts[i] > 0.0f) event.mix.push_back({pigments[i].name, s.mix_parts[i]});
  }
  return event;
}

// The state a window opens with: D65, the options' wavelengths and quality, the brush heads
// and presets found, the recent files.
WindowState initial_window_state(const PaintOptions& options);

}  // namespace impasto::app::window
