#pragma once
// What the painting window's panels show and change, shared by the frame loop
// (paint_window.cpp) and the panels (panels.cpp).
#include <impasto/input/hid_device.hpp>
#include <impasto/paintcore/brush.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render_gl/canvas_view.hpp>
#include <impasto/render_gl/gpu_view_options.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "window/sim_worker.hpp"
#include "window/tablet_input.hpp"

namespace impasto::app::window {

// An action that discards the painting, held while the unsaved-changes prompt is open.
enum class PendingAction { kNone, kNew, kOpen, kOpenRecent, kQuit };

struct WindowState {
  // --- look (shared with the CPU renderer's settings) ---
  render::RenderSettings settings;
  render_gl::GpuViewOptions view_options;
  bool settings_changed = true;  // palette and dry bake must be rebuilt
  bool use_blackbody = false;
  int illuminant = 0;  // index into illuminants
  float kelvin = 5600.0f;
  std::vector<std::string> illuminants;

  // --- paint on the brush ---
  std::vector<float> mix_parts;  // per pigment of the database
  float load_volume_mm3 = 40.0f;
  std::array<float, 3> swatch_rgb{0.5f, 0.5f, 0.5f};
  bool mix_changed = true;

  // --- brush and pen ---
  paintcore::BrushSettings brush{"round", 6.0, 0.5};
  std::vector<std::string> brush_heads;
  bool pressure_from_speed = false;
  float mouse_pressure = 0.6f;

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
  std::optional<std::filesystem::path> file;  // the painting's file, once saved or opened
  std::vector<std::filesystem::path> recent;
  PendingAction pending = PendingAction::kNone;
  bool pending_confirmed = false;  // no unsaved changes, or the user said to go ahead
  std::filesystem::path pending_path;
  std::string path_input;
  int new_width = 1024, new_height = 768;
  float new_dpi = 150.0f;
  std::string message;  // the last file operation's result or error

  // --- status ---
  double frame_ms = 0.0;
  double upload_ms = 0.0;
  int tiles_uploaded = 0;
  long long pixels_shaded = 0;     // by the last frame's K-M pass (the rest was cached)
  double input_latency_ms = -1.0;  // median, pen event to the swap showing it (< 0: none yet)
  std::array<double, 2> cursor_cell{-1, -1};
  bool quit = false;
};

}  // namespace impasto::app::window
