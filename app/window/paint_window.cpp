// The painting window: GLFW + OpenGL 3.3 core (glad) + Dear ImGui. The canvas is shaded on
// the GPU by render_gl::CanvasRenderer, fed with the tiles the simulation dirtied; the
// simulation runs on session::SimWorker's thread.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the panels' rectangles, to tell where a press landed
#include <impasto/data/cie.hpp>
#include <impasto/input/stroke_import.hpp>
#include <impasto/paintcore/brush_head.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/node_cache.hpp>
#include <impasto/render/render_painting.hpp>
#include <impasto/render_gl/canvas_renderer.hpp>
#include <impasto/render_gl/gl.hpp>
#include <impasto/render_gl/shaded_view_cache.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "impasto/files/message_text.hpp"
#include "impasto/session/disk_stamp.hpp"
#include "impasto/session/pen_feed.hpp"
#include "impasto/session/preview.hpp"
#include "impasto/session/rebuild.hpp"
#include "impasto/session/recent_files.hpp"
#include "impasto/session/recovery_folder.hpp"
#include "impasto/session/session_registry.hpp"
#include "impasto/session/session_start.hpp"
#include "impasto/session/sim_worker.hpp"
#include "latency_lines.hpp"
#include "window/brush_outline.hpp"
#include "window/brush_outline_overlay.hpp"
#include "window/canvas_menu.hpp"
#include "window/canvas_viewer.hpp"
#include "window/document.hpp"
#include "window/edit_help_menus.hpp"
#include "window/eyedropper.hpp"
#include "window/opening_note.hpp"
#include "window/paint_options.hpp"
#include "window/palette_board_panel.hpp"
#include "window/panels.hpp"
#include "window/pigment_drift_note.hpp"
#include "window/pigment_editor.hpp"
#include "window/pointer_events.hpp"
#include "window/pointer_gestures.hpp"
#include "window/pointer_latency.hpp"
#include "window/pointer_server_times.hpp"
#include "window/screenshot.hpp"
#include "window/session_banner.hpp"
#include "window/shortcuts.hpp"
#include "window/swatch_chips.hpp"
#include "window/tablet_input.hpp"
#include "window/tablets.hpp"
#include "window/tool_bar.hpp"
#include "window/ui_damage.hpp"
#include "window/window_present.hpp"
#include "window/window_title.hpp"

namespace impasto::app::window {
namespace {

using Clock = std::chrono::steady_clock;

// A wheel notch zooms by a quarter, as image editors do: five notches are about 3x.
constexpr double kZoomPerWheelNotch = 1.25;

// Set by SIGTERM, SIGINT and SIGHUP (a logout, Ctrl+C): the window closes at the next frame,
// keeping unsaved work recoverable instead of asking.
std::atomic<bool> g_terminate{false};

extern "C" void request_termination(int) {
  g_terminate.store(true);
}

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The shortest time between frames while nothing changes (see run()).
constexpr auto kIdleFrame = std::chrono::milliseconds(8);

// The width the panels take at the window's right (pixels): the canvas is fitted left of it.
constexpr int kPanelsWidth = 360;
// How long an opening window waits for its palette's rule (built on first use of a set of
// pigments, then cached) before it shades the painting with the stand-in.
constexpr double kRuleWait_s = 3.0;

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

static_assert(kLeftButton == GLFW_MOUSE_BUTTON_LEFT && kRightButton == GLFW_MOUSE_BUTTON_RIGHT &&
              kMiddleButton == GLFW_MOUSE_BUTTON_MIDDLE);

// Whether ImGui's last frame drew something that takes a mouse press at (x, y): a panel, the
// menu bar, the status bar, or any open popup (a menu, the unsaved-changes prompt). This is
// the rule behind io.WantCaptureMouse, asked for where the press happened rather than
// where the cursor is at the frame.
bool ui_at(double x, double y) {
  const ImGuiContext& g = *GImGui;
  if (g.OpenPopupStack.Size > 0) return true;
  const ImVec2 p(static_cast<float>(x), static_cast<float>(y));
  for (const ImGuiWindow* window : g.Windows) {
    if (window->Active && !window->Hidden && !(window->Flags & ImGuiWindowFlags_NoMouseInputs) &&
        window->OuterRectClipped.Contains(p)) {
      return true;
    }
  }
  return false;
}

struct GlfwLibrary {
  GlfwLibrary() {
    glfwSetErrorCallback([](int code, const char* text) {
      std::cerr << "impasto: GLFW error " << code << ": " << text << "\n";
    });
    if (!glfwInit()) {
      throw std::runtime_error(
          "cannot open a window: GLFW found no display (set DISPLAY, or "
          "run under xvfb-run)");
    }
  }
  ~GlfwLibrary() { glfwTerminate(); }
};

class PaintWindow {
 public:
  explicit PaintWindow(const PaintOptions& options);
  ~PaintWindow();
  void run();

 private:
  void create_window();
  void note_an_empty_brush();
  void sync_gpu();
  void handle_canvas_input();
  void handle_shortcuts();
  void run_commands();
  void pick_at(const PointerEvent& at, bool released);
  void update_pick_cursor();
  void update_title();
  void update_swatch();
  void draw_frame(bool take_screenshot);
  // A frame's canvas, shaded as the view's motion and the canvas's changes allow, and shown.
  void draw_canvas(int fb_w, int fb_h, int win_w, bool take_screenshot);
  // An opening frame (opening_): the panels over the view's background, the note among them.
  void present_opening(int fb_w, int fb_h);
  void present_frame(const std::vector<render_gl::PixelRect>& canvas_changed, int fb_w, int fb_h,
                     double fb_scale, bool take_screenshot);
  void pen_sample(const PointerEvent& at, bool tip_down);
  void pan_view(double from_x, double from_y, double to_x, double to_y, double time_s);
  void rotate_view(double from_x, double from_y, double to_x, double to_y, double time_s);
  void time_view_motion(double swap_time_s);
  void submit_pen_event(input::StrokeEvent event);
  void report_latency() const;
  TabletTargetGeometry tablet_geometry() const;
  PaintingSnapshot snapshot();
  // The document replaced its painting (new, open, recovered, reframed): the view starts again.
  void painting_replaced();
  session::SimWorker& worker() { return document_->worker(); }

  PaintOptions options_;
  GlfwLibrary glfw_;
  GLFWwindow* window_ = nullptr;
  WindowState state_;
  std::unique_ptr<WindowPresenter> presenter_;  // frames present only what changed
  UiDamage ui_damage_;
  bool present_whole_ = true;  // the window's pixels may be lost: the next frame shows them all
  int presented_w_ = 0, presented_h_ = 0;
  bool frame_changed_ = true;  // the last frame re-shaded some of the canvas
  double tip_down_s_ = -1e9;   // when the last sample with the tip down came
  // The first frames: the panels and a note (opening_note.hpp) until the palette's own rule is
  // built, for at most kRuleWait_s (the view is then shaded whole once, not twice).
  bool opening_ = true;

  // Every pen sample, mouse or tablet, goes to the simulation through this feed.
  session::PenFeed canvas_feed_{
      [this](input::StrokeEvent event) { submit_pen_event(std::move(event)); }};
  InputLatency latency_;      // pen sample's own time -> the swap that shows it
  ViewLatency view_latency_;  // a zoom step's, rotation's, pan's or light's event -> the swap
  std::vector<double> frame_pointer_times_;  // this frame's presses and moves (a light drag's)
  std::array<double, 2> shown_light_{};      // the light's direction at the last swap
  std::vector<int> coarse_factors_;          // of each coarse frame, for the report
  std::uint64_t applied_at_upload_ = 0;      // simulation jobs applied before this frame's upload
  PaletteBoardPanel board_panel_;
  PigmentEditor pigment_editor_;
  CanvasMenu canvas_menu_;
  PigmentDriftNote pigment_drift_;
  SwatchChips swatch_chips_;

  std::unique_ptr<Tablets> tablets_;  // read on their own threads, polled once a frame

  // The mouse: every event from GLFW's callbacks, applied in order once a frame.
  PointerEventQueue pointer_events_;
  std::unique_ptr<PointerServerTimes> server_times_;  // each event's time, from the X server
  PointerGestures gestures_{{
      [this](const PointerEvent& at, bool tip_down) { pen_sample(at, tip_down); },
      [this](double fx, double fy, double tx, double ty, double t) { pan_view(fx, fy, tx, ty, t); },
      [this](double fx, double fy, double tx, double ty, double t) {
        rotate_view(fx, fy, tx, ty, t);
      },
  }};
  SpeedPressure speed_pressure_;
  // The keyboard: each key press (and a held key's repeats) since the last frame, in order.
  struct KeyPress {
    int key, mods;
    bool repeat;
  };
  std::vector<KeyPress> key_presses_;
  PickGesture pick_gesture_;        // the eyedropper's presses on the canvas
  bool pick_cursor_ = false;        // the cursor is the eyedropper's this frame
  PointerOverlay pointer_overlay_;  // the brush's outline and the empty-brush note
  GLFWcursor* crosshair_ = nullptr;
  std::string head_before_knife_ = "round";  // where B returns to from the knife (K)
  int window_w_ = 0, window_h_ = 0;          // this frame's window size
  double session_start_s_ = 0;

  // The painting and its session (after the panels: it opens the board beside the painting).
  std::unique_ptr<Document> document_;
  std::unique_ptr<CanvasViewer> viewer_;  // the painting on the GPU and its shaded view
  // The preview of a session offered for recovery, as a texture (released with the window's
  // context, in the destructor).
  std::unique_ptr<PreviewTexture> preview_ = std::make_unique<PreviewTexture>();
  std::string shown_title_;
};

PaintWindow::PaintWindow(const PaintOptions& options) : options_(options) {
  state_.settings.wavelengths = options.wavelengths;
  state_.illuminants = data::illuminant_names();
  const auto d65 = std::find(state_.illuminants.begin(), state_.illuminants.end(), "D65");
  state_.illuminant =
      d65 == state_.illuminants.end() ? 0 : static_cast<int>(d65 - state_.illuminants.begin());
  state_.brush_heads = brush_heads();
  reload_presets(state_);
  state_.recent = session::load_recent_files();
  create_window();
  document_ = std::make_unique<Document>(options_, state_, board_panel_);
  viewer_ = std::make_unique<CanvasViewer>(worker());
  tablets_ = std::make_unique<Tablets>(glfwGetTime() - session_start_s_, state_);
}

PaintWindow::~PaintWindow() {
  tablets_.reset();
  document_.reset();
  viewer_.reset();
  preview_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (crosshair_) glfwDestroyCursor(crosshair_);
  if (window_) glfwDestroyWindow(window_);
}

void PaintWindow::create_window() {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(options_.window_width, options_.window_height,
                             window_title(options_.painting, false).c_str(), nullptr, nullptr);
  if (!window_) throw std::runtime_error("cannot open a window with OpenGL 3.3 core");
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  render_gl::load_gl(reinterpret_cast<GLADloadfunc>(&glfwGetProcAddress));
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // panels are laid out in code, nothing to remember
  ImGui::StyleColorsDark();
  // The mouse's events are queued with their times as they arrive. Installed before ImGui's
  // backend, which keeps our button callback and calls it before its own.
  server_times_ = std::make_unique<PointerServerTimes>(window_);
  glfwSetWindowUserPointer(window_, this);
  glfwSetCursorPosCallback(window_, [](GLFWwindow* window, double x, double y) {
    auto* self = static_cast<PaintWindow*>(glfwGetWindowUserPointer(window));
    self->pointer_events_.moved(x, y, self->server_times_->move_time(x, y));
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* window, int button, int action, int) {
    auto* self = static_cast<PaintWindow*>(glfwGetWindowUserPointer(window));
    const bool pressed = action == GLFW_PRESS;
    self->pointer_events_.button(button, pressed,
                                 self->server_times_->button_time(button, pressed));
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* window, double, double) {
    auto* self = static_cast<PaintWindow*>(glfwGetWindowUserPointer(window));
    self->view_latency_.submitted(ViewMotion::kZoom, self->server_times_->wheel_time());
  });
  double cursor_x = 0, cursor_y = 0;
  glfwGetCursorPos(window_, &cursor_x, &cursor_y);
  pointer_events_.set_position(cursor_x, cursor_y);
  // Exposed again after being covered: the window's pixels are drawn whole.
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow* window) {
    static_cast<PaintWindow*>(glfwGetWindowUserPointer(window))->present_whole_ = true;
  });
  presenter_ = std::make_unique<WindowPresenter>(window_);
  // Key presses are queued as they arrive (a press and release within one frame still
  // counts); ImGui's backend, installed next, calls this before its own.
  glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    static_cast<PaintWindow*>(glfwGetWindowUserPointer(window))
        ->key_presses_.push_back({key, mods, action == GLFW_REPEAT});
  });
  crosshair_ = glfwCreateStandardCursor(GLFW_CROSSHAIR_CURSOR);
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  session_start_s_ = glfwGetTime();
}

void PaintWindow::painting_replaced() {
  viewer_->painting_replaced();
}

// A stroke begun with nothing on the brush paints nothing: say so where the pointer is, once a
// session (only when every event is applied, so a Load brush still queued is not missed).
void PaintWindow::note_an_empty_brush() {
  if (!worker().idle()) return;
  pointer_overlay_.stroke_began(
      worker().with_painting([](const paintcore::Painting& p) { return p.brush_totals().volume; }),
      glfwGetTime());
}

TabletTargetGeometry PaintWindow::tablet_geometry() const {
  TabletTargetGeometry geometry;
  glfwGetWindowSize(window_, &geometry.window_w, &geometry.window_h);
  int wx = 0, wy = 0;
  glfwGetWindowPos(window_, &wx, &wy);
  geometry.window_origin_px = {static_cast<double>(wx), static_cast<double>(wy)};
  geometry.screen_px = {static_cast<double>(wx), static_cast<double>(wy),
                        static_cast<double>(geometry.window_w),
                        static_cast<double>(geometry.window_h)};
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int mx = 0, my = 0;
    glfwGetMonitorPos(monitor, &mx, &my);
    if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) {
      geometry.screen_px = {static_cast<double>(mx), static_cast<double>(my),
                            static_cast<double>(mode->width), static_cast<double>(mode->height)};
    }
  }
  geometry.view = state_.view;
  geometry.canvas_w_cells = viewer_->width_cells();
  geometry.canvas_h_cells = viewer_->height_cells();
  geometry.cell_mm = viewer_->cell_mm();
  return geometry;
}

PaintingSnapshot PaintWindow::snapshot() {
  return worker().with_painting([](const paintcore::Painting& p) {
    PaintingSnapshot s;
    s.width_cells = p.canvas().width_cells();
    s.height_cells = p.canvas().height_cells();
    s.dpi = p.canvas().spec().dpi;
    s.undo_depth = p.undo_depth();
    s.redo_depth = p.redo_depth();
    s.dry_layers = p.canvas().dry_layers().size();
    s.slots = p.pigment_slots();
    s.brush_volume_mm3 = p.brush_totals().volume;
    s.brush_head = p.brush().head();
    s.brush_cells = p.brush().cells_across();
    return s;
  });
}

// Brings the GPU textures up to date: every tile after a new painting, light or slot table;
// otherwise only the tiles the simulation dirtied since the last frame.
void PaintWindow::sync_gpu() {
  // Every job applied by now has dirtied its tiles before the upload below takes them.
  applied_at_upload_ = worker().stats().applied;
  viewer_->sync(worker(), state_, canvas_feed_.in_stroke(), glfwGetTime());
}

// The Palette panel's chips, painted and rendered off the UI thread (swatch_chips.hpp).
void PaintWindow::update_swatch() {
  const paintcore::CanvasSpec canvas =
      worker().with_painting([](const paintcore::Painting& p) { return p.canvas().spec(); });
  swatch_chips_.update(state_, canvas);
}

void PaintWindow::pen_sample(const PointerEvent& at, bool tip_down) {
  const auto cell = state_.view.window_to_cell(at.x, at.y, window_w_, window_h_);
  const double cell_mm = viewer_->cell_mm();
  paintcore::PenSample sample;
  sample.time_s = at.time_s - session_start_s_;  // the event's own time
  sample.x_mm = cell[0] * cell_mm;
  sample.y_mm = cell[1] * cell_mm;
  if (tip_down && !canvas_feed_.in_stroke()) {
    speed_pressure_.start_stroke();
    note_an_empty_brush();
  }
  const float pressure = state_.pressure_from_speed
                             ? speed_pressure_.at(sample.x_mm, sample.y_mm, sample.time_s)
                             : state_.mouse_pressure;
  sample.pressure = tip_down ? pressure : 0.0f;
  sample.buttons = paintcore::kPenInRange | (tip_down ? paintcore::kPenTip : 0u);
  canvas_feed_.feed(sample);
}

void PaintWindow::submit_pen_event(input::StrokeEvent event) {
  const auto* sample = std::get_if<input::SampleEvent>(&event);
  const double time_s = sample ? sample->sample.time_s : 0.0;
  worker().submit(std::move(event));
  const double now = glfwGetTime();
  document_->note_input(now);
  // Only this thread submits, so the count just read is this event's job number.
  if (sample) latency_.submitted(worker().stats().submitted, time_s);
  if (sample && (sample->sample.buttons & paintcore::kPenTip) != 0) tip_down_s_ = now;
}

void PaintWindow::pan_view(double from_x, double from_y, double to_x, double to_y, double time_s) {
  const auto a = state_.view.window_to_cell(from_x, from_y, window_w_, window_h_);
  const auto b = state_.view.window_to_cell(to_x, to_y, window_w_, window_h_);
  state_.view.center_x_cells -= b[0] - a[0];
  state_.view.center_y_cells -= b[1] - a[1];
  view_latency_.submitted(ViewMotion::kPan, time_s);
  view_latency_.applied(ViewMotion::kPan);
}

void PaintWindow::rotate_view(double from_x, double from_y, double to_x, double to_y,
                              double time_s) {
  const double a0 = std::atan2(from_y - window_h_ / 2.0, from_x - window_w_ / 2.0);
  const double a1 = std::atan2(to_y - window_h_ / 2.0, to_x - window_w_ / 2.0);
  state_.view.rotation_rad += a1 - a0;
  view_latency_.submitted(ViewMotion::kRotate, time_s);
  view_latency_.applied(ViewMotion::kRotate);
}

// A frame was swapped at swap_time_s: it shows every view motion applied before it. The
// Light panel's disc moves the light as ImGui reads this frame's pointer events, so when the
// light's direction changed, those events moved it.
void PaintWindow::time_view_motion(double swap_time_s) {
  const std::array<double, 2> light = {state_.settings.light_azimuth_deg,
                                       state_.settings.light_elevation_deg};
  if (light != shown_light_) {
    for (const double t : frame_pointer_times_) view_latency_.submitted(ViewMotion::kLight, t);
    view_latency_.applied(ViewMotion::kLight);
  }
  shown_light_ = light;
  view_latency_.shown(swap_time_s);
  // A drag's move that arrives while a frame is drawn waits for it, then for its own frame:
  // the two fit the 100 ms.
  viewer_->set_moving(view_latency_.moving());
}

// Applies every mouse event since the last frame in order: each move of a stroke is a pen
// sample with its own time, and each press and release starts or ends its drag where it
// happened.
void PaintWindow::handle_canvas_input() {
  const ImGuiIO& io = ImGui::GetIO();
  glfwGetWindowSize(window_, &window_w_, &window_h_);
  PointerFrame frame;
  frame.space_down = glfwGetKey(window_, GLFW_KEY_SPACE) == GLFW_PRESS;
  // While a tablet's pen is near, it paints: it moves the cursor and presses the button
  // too, and its own samples carry the real pressure.
  frame.tablet_near = tablets_->near(glfwGetTime());
  frame.canvas_at = [](double x, double y) { return !ui_at(x, y); };
  // The eyedropper (its tool, or Alt held) takes left presses on the canvas; a stroke under
  // way goes on to its end.
  const bool alt = glfwGetKey(window_, GLFW_KEY_LEFT_ALT) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
  const bool picking = (state_.eyedropper.tool || alt) && !gestures_.painting();
  const std::vector<PointerEvent> events = pick_gesture_.take_picks(
      pointer_events_.take(), picking, frame.canvas_at,
      [this](const PointerEvent& at, bool released) { pick_at(at, released); });
  gestures_.apply(events, frame);
  frame_pointer_times_.clear();
  for (const PointerEvent& event : events) {
    if (event.action != PointerAction::kRelease) frame_pointer_times_.push_back(event.time_s);
  }

  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  pick_cursor_ = pick_gesture_.held() || (picking && !ui_at(x, y));
  // (Asked here, between frames: within one, ImGui's implicit Debug window covers the canvas.)
  pointer_overlay_.set_on_canvas(!ui_at(x, y));
  update_pick_cursor();
  state_.cursor_cell = state_.view.window_to_cell(x, y, window_w_, window_h_);
  // Zoom about the cursor with the wheel, down to single cells and up to 64 px a cell.
  if (!io.WantCaptureMouse && io.MouseWheel != 0.0f) {
    const auto before = state_.view.window_to_cell(x, y, window_w_, window_h_);
    state_.view.pixels_per_cell = std::clamp(
        state_.view.pixels_per_cell * std::pow(kZoomPerWheelNotch, io.MouseWheel), 0.02, 64.0);
    const auto after = state_.view.window_to_cell(x, y, window_w_, window_h_);
    state_.view.center_x_cells += before[0] - after[0];
    state_.view.center_y_cells += before[1] - after[1];
    view_latency_.applied(ViewMotion::kZoom);
  }
  // A wheel click over a panel scrolled it: no zoom step to time.
  if (io.WantCaptureMouse && io.MouseWheel != 0.0f) view_latency_.dropped(ViewMotion::kZoom);
}

// Keys become commands through the one table (shortcuts.hpp), unless a text field or a
// dialog or menu has the keyboard.
void PaintWindow::handle_shortcuts() {
  const std::vector<KeyPress> keys = std::exchange(key_presses_, {});
  const bool typing = ImGui::GetIO().WantTextInput || GImGui->OpenPopupStack.Size > 0;
  if (!typing) {
    for (const KeyPress& press : keys) {
      if (const auto command = command_for_key(press.key, press.mods, press.repeat))
        state_.commands.push_back(*command);
    }
  }
  run_commands();
}

// Carries out what the keys and the menus asked for (the File menu's own at its next frame).
// A brush change waits for the stroke under way to end.
void PaintWindow::run_commands() {
  std::vector<Command> waiting;
  const auto set_brush = [&](Command command, auto&& change) {
    if (canvas_feed_.in_stroke()) {
      waiting.push_back(command);
      return;
    }
    change();
    worker().submit(brush_event(state_));
  };
  for (const Command command : std::exchange(state_.commands, {})) {
    paintcore::BrushSettings& brush = state_.brush;
    switch (command) {
      case Command::kNew:
        state_.file_command = FileCommand::kNew;
        break;
      case Command::kOpen:
        state_.file_command = FileCommand::kOpen;
        break;
      case Command::kSave:
        state_.file_command = FileCommand::kSave;
        break;
      case Command::kSaveAs:
        state_.file_command = FileCommand::kSaveAs;
        break;
      case Command::kUndo:
        worker().submit(input::UndoEvent{});
        break;
      case Command::kRedo:
        worker().submit(input::RedoEvent{});
        break;
      case Command::kBrush:
        state_.eyedropper.tool = false;
        if (brush.head == "knife") set_brush(command, [&] { brush.head = head_before_knife_; });
        break;
      case Command::kKnife:
        state_.eyedropper.tool = false;
        if (brush.head != "knife" && std::find(state_.brush_heads.begin(), state_.brush_heads.end(),
                                               "knife") != state_.brush_heads.end()) {
          set_brush(command, [&] {
            head_before_knife_ = brush.head;
            brush.head = "knife";
          });
        }
        break;
      case Command::kEyedropper:
        state_.eyedropper.tool = !state_.eyedropper.tool;
        break;
      case Command::kBrushSmaller:
      case Command::kBrushLarger:
        set_brush(command, [&] {
          const double factor =
              command == Command::kBrushLarger ? kBrushSizeStep : 1.0 / kBrushSizeStep;
          brush.size_mm = std::clamp(brush.size_mm * factor, kBrushSizeMinMm, kBrushSizeMaxMm);
        });
        break;
      case Command::kFitCanvas:
        state_.fit_requested = true;
        break;
      case Command::kOneCellPerPixel:
        state_.view.pixels_per_cell = 1.0;
        break;
      case Command::kShowShortcuts:
        state_.show_shortcuts = !state_.show_shortcuts;
        break;
    }
  }
  state_.commands.insert(state_.commands.begin(), waiting.begin(), waiting.end());
}

// The eyedropper at a window position: the paint there is shown as the mouse moves; where
// the button is released it becomes the palette's mix and (load on pick) the brush's paint.
void PaintWindow::pick_at(const PointerEvent& at, bool released) {
  EyedropperState& e = state_.eyedropper;
  const auto cell = state_.view.window_to_cell(at.x, at.y, window_w_, window_h_);
  if (released) worker().wait_idle();  // the paint the user sees, every stroke applied
  std::optional<PickedPaint> picked = worker().with_painting(
      [&](const paintcore::Painting& painting) { return pick_paint(painting, cell[0], cell[1]); });
  if (!picked) {
    if (released) e.message = "nothing to pick here: bare canvas";
    return;
  }
  e.picked = std::move(picked);
  e.message.clear();
  if (!released) return;
  e.reveal = true;
  try {
    render_picked_colours(*e.picked, state_.settings);
  } catch (const std::exception& error) {
    e.message = error.what();
  }
  const std::vector<std::string> unknown = set_palette_mix(e.picked->mix, state_.mix_parts);
  set_palette_medium(*e.picked, state_.paint_medium, state_.paint_medium_amount);
  state_.mix_changed = true;
  if (!unknown.empty())
    e.message = "not in the pigment library, left out of the palette: " + unknown.front();
  if (e.load_on_pick)
    load_onto_brush(worker(), picked_load(*e.picked, state_.load_volume_mm3, state_.paint_body));
}

// The crosshair while the eyedropper would pick (ImGui leaves the cursor alone meanwhile).
void PaintWindow::update_pick_cursor() {
  ImGuiIO& io = ImGui::GetIO();
  const bool was = (io.ConfigFlags & ImGuiConfigFlags_NoMouseCursorChange) != 0;
  if (pick_cursor_ == was) return;
  if (pick_cursor_) {
    io.ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange;
    glfwSetCursor(window_, crosshair_);
  } else {
    io.ConfigFlags &= ~ImGuiConfigFlags_NoMouseCursorChange;
    glfwSetCursor(window_, nullptr);
  }
}

// The window's title: the painting's file name (or Untitled), marked while unsaved.
void PaintWindow::update_title() {
  const std::string title = window_title(state_.file, worker().stats().events_since_save > 0);
  if (title == shown_title_) return;
  glfwSetWindowTitle(window_, title.c_str());
  shown_title_ = title;
}

// Puts the frame on screen: the cached canvas with ImGui's panels over it. Where the back
// buffer keeps the last frame (WindowPresenter::partial), only what changed is drawn again
// and presented — the canvas's re-shaded regions and the panels' changed parts — each
// rectangle as the cached canvas with every panel over it, so a pixel drawn is drawn whole.
void PaintWindow::present_frame(const std::vector<render_gl::PixelRect>& canvas_changed, int fb_w,
                                int fb_h, double fb_scale, bool take_screenshot) {
  ImDrawData& ui = *ImGui::GetDrawData();
  for (const std::uintptr_t texture : state_.ui_textures_changed)
    ui_damage_.texture_changed(texture);
  state_.ui_textures_changed.clear();
  const std::vector<UiRect> ui_changed = ui_damage_.update(ui);
  const bool whole = !presenter_->partial() || present_whole_ || take_screenshot ||
                     fb_w != presented_w_ || fb_h != presented_h_;
  present_whole_ = false;
  presented_w_ = fb_w;
  presented_h_ = fb_h;
  glViewport(0, 0, fb_w, fb_h);
  if (whole) {
    viewer_->copy_to(0, {0, 0, fb_w, fb_h});
    ImGui_ImplOpenGL3_RenderDrawData(&ui);
    if (take_screenshot) save_window_screenshot(*options_.screenshot, fb_w, fb_h);
    presenter_->present_all();
    return;
  }
  std::vector<render_gl::PixelRect> rects = canvas_changed;
  for (const UiRect& r : ui_changed) rects.push_back(to_gl_pixels(r, fb_scale, fb_w, fb_h));
  rects = merge_rects(std::move(rects));
  for (const render_gl::PixelRect& r : rects) {
    viewer_->copy_to(0, r);
    const ClipDrawData clipped(ui, to_ui_rect(r, fb_scale, fb_h));
    ImGui_ImplOpenGL3_RenderDrawData(&ui);
  }
  presenter_->present_parts(rects);
}

// How long a frame waits for the simulation to apply the pen samples it has just submitted:
// shown by this frame instead of the next, they reach the screen a frame sooner, and the
// simulation has its own core meanwhile.
constexpr auto kSimWait = std::chrono::milliseconds(15);

void PaintWindow::draw_frame(bool take_screenshot) {
  const auto start = Clock::now();
  if (worker().stats().submitted != applied_at_upload_) worker().wait_idle_for(kSimWait);
  update_swatch();
  sync_gpu();
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  int win_w = 0, win_h = 0;
  glfwGetWindowSize(window_, &win_w, &win_h);
  if (state_.fit_requested && fb_w > 0) {
    // Fit into the part of the window left of the panels.
    state_.view = render_gl::fit_canvas(viewer_->width_cells(), viewer_->height_cells(),
                                        std::max(win_w - kPanelsWidth, 100), win_h - 60);
    // (shifted right of centre)
    state_.view.center_x_cells += 0.5 * kPanelsWidth / state_.view.pixels_per_cell;
    state_.fit_requested = false;
  }

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const PaintingSnapshot painting = snapshot();
  const FileActions files = document_->file_actions();
  PanelContext context{state_, worker(), painting, viewer_->palette(), files, board_panel_};
  draw_panels(context);
  draw_tool_bar(state_, worker(), painting.brush_volume_mm3);
  draw_session_banners(worker().stats(), document_->notice());
  pigment_editor_.draw(state_, viewer_->palette());
  const CanvasMenuRequest canvas_request =
      canvas_menu_.draw(viewer_->width_cells(), viewer_->height_cells(), state_.file);
  if (ImGui::BeginMainMenuBar()) {  // Help, last on the menu bar
    help_menu(state_);
    ImGui::EndMainMenuBar();
  }
  draw_help_windows(state_);
  double cursor_x = 0, cursor_y = 0;
  glfwGetCursorPos(window_, &cursor_x, &cursor_y);
  if (pick_cursor_) {
    draw_pick_cursor(state_, static_cast<float>(cursor_x), static_cast<float>(cursor_y));
  } else {
    pointer_overlay_.draw(painting, state_.mouse_pressure, state_.view, window_w_, window_h_,
                          cursor_x, cursor_y, glfwGetTime());
  }
  pigment_drift_.draw(state_, worker());
  std::optional<RecoveryPreview> preview;
  if (document_->previewing() && document_->preview()) {
    preview = RecoveryPreview{*document_->previewing(), preview_->texture(), preview_->width(),
                              preview_->height(), document_->preview()->base};
  }
  const RecoveryChoice recovery = draw_recovery_offer(document_->recoverable(), preview);
  const bool opening = opening_ && !take_screenshot;
  if (opening) draw_opening_note(win_w, win_h, kPanelsWidth);
  ImGui::Render();
  if (opening)
    present_opening(fb_w, fb_h);
  else
    draw_canvas(fb_w, fb_h, win_w, take_screenshot);
  state_.frame_ms = ms_since(start);
  switch (document_->recover(recovery)) {
    case Document::Recovered::kPreviewReady:
      preview_->show(document_->preview()->painting);
      break;
    case Document::Recovered::kReplaced:
      painting_replaced();
      break;
    case Document::Recovered::kNothing:
      break;
  }
  if (document_->apply_canvas_request(canvas_request)) painting_replaced();
}

void PaintWindow::present_opening(int fb_w, int fb_h) {
  clear_to_background(state_.view_options.background_rgb, fb_w, fb_h);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  presenter_->present_all();
  present_whole_ = true;
  opening_ = viewer_->palette_stands_in() && glfwGetTime() - session_start_s_ < kRuleWait_s;
  frame_changed_ = false;  // the loop idles between these frames: the rule has the cores
}

void PaintWindow::draw_canvas(int fb_w, int fb_h, int win_w, bool take_screenshot) {
  // The view is in window coordinates; scale it to framebuffer pixels (HiDPI).
  render_gl::CanvasView fb_view = state_.view;
  const double fb_scale = win_w > 0 ? static_cast<double>(fb_w) / win_w : 1.0;
  fb_view.pixels_per_cell *= fb_scale;
  const render_gl::CachedDrawStats canvas =
      viewer_->shade(state_, fb_view, fb_w, fb_h, take_screenshot, canvas_feed_.in_stroke(),
                     glfwGetTime(), tip_down_s_);
  state_.pixels_shaded += canvas.pixels_shaded;
  frame_changed_ = !canvas.changed.empty();
  present_frame(canvas.changed, fb_w, fb_h, fb_scale, take_screenshot);
  latency_.shown(applied_at_upload_, glfwGetTime() - session_start_s_);
  time_view_motion(glfwGetTime());
  if (canvas.coarse) coarse_factors_.push_back(canvas.coarse_factor);
  state_.input_latency_ms = latency_.recent_median_ms().value_or(-1.0);
  state_.input_latency_p95_ms = latency_.recent_percentile_ms(0.95).value_or(-1.0);
  state_.input_behind_ms = latency_.behind_ms(glfwGetTime() - session_start_s_);
}

void PaintWindow::run() {
  int frames_since_idle = 0;
  bool screenshot_done = !options_.screenshot;
  for (int signal : {SIGTERM, SIGINT, SIGHUP}) std::signal(signal, request_termination);
  bool terminated = false;
  while (!state_.quit) {
    if (g_terminate.load()) {
      terminated = true;
      break;
    }
    server_times_->scan();  // the waiting events' own times, before GLFW delivers them
    glfwPollEvents();
    if (glfwWindowShouldClose(window_)) {
      glfwSetWindowShouldClose(window_, GLFW_FALSE);
      if (options_.exit_after) break;
      // As File > Quit: with unsaved changes, Save / Discard / Cancel.
      state_.file_command = FileCommand::kQuit;
    }
    if (document_->run_pending_action()) painting_replaced();
    if (state_.quit) break;
    update_title();
    // Reports written to the older status line are shown as notifications.
    handle_shortcuts();
    tablets_->poll(
        state_, [this] { return tablet_geometry(); }, canvas_feed_, glfwGetTime());
    handle_canvas_input();
    // A scripted run waits until the replay is applied, the palette's own rule is built and a
    // few frames have laid out the panels, then captures the whole window.
    frames_since_idle =
        worker().idle() && !viewer_->palette_stands_in() ? frames_since_idle + 1 : 0;
    const bool capture = !screenshot_done && frames_since_idle >= 3;
    const auto frame_start = Clock::now();
    draw_frame(capture);
    // Nothing new on the canvas and nothing to simulate: frames at most every kIdleFrame, so
    // the simulation and the rest of the machine get the cores (an event still waits less).
    if (!frame_changed_ && worker().idle()) std::this_thread::sleep_until(frame_start + kIdleFrame);
    // Pen up and nothing to simulate: the GPU makes room for the next strokes' tiles now, when
    // a growth of its tile atlas delays no stroke.
    if (!canvas_feed_.in_stroke() && worker().idle()) viewer_->make_room();
    if (capture) {
      screenshot_done = true;
      std::cout << "wrote " << options_.screenshot->string() << "\n";
    }
    document_->maybe_autosave(glfwGetTime(), canvas_feed_.in_stroke());
    document_->note_recording_failure();
    if (options_.exit_after && screenshot_done && worker().idle()) break;
  }
  report_latency();
  document_->close(terminated);
}

// The session's input latency, for measuring it (docs/measurements/window.md, "Latency").
void PaintWindow::report_latency() const {
  std::cout << view_latency_.report(coarse_factors_);
  if (latency_.shown_count() == 0) return;
  std::cout << latency_line("input", "pen event", "samples",
                            {*latency_.percentile_ms(0.5), *latency_.percentile_ms(0.95),
                             static_cast<int>(latency_.shown_count())})
            << "; " << server_times_->matched() << " mouse events timed by the window "
            << "system, " << server_times_->unmatched() << " when delivered\n";
}

}  // namespace

void run_paint_window(const PaintOptions& options) {
  PaintWindow window(options);
  window.run();
}

}  // namespace impasto::app::window
