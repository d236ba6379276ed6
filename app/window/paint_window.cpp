// The painting window: a frame loop in the shape of Dear ImGui's GLFW + OpenGL 3 example,
// over four parts: the shell (GLFW, ImGui, presentation; window_shell.hpp), the document
// (the painting and its session; document.hpp), the canvas viewer (the painting on the GPU,
// shaded; canvas_viewer.hpp) and the input router (pointer, tablets, keys, eyedropper;
// input_router.hpp). The simulation runs on session::SimWorker's thread.
#include <imgui.h>

#include <array>
#include <chrono>
#include <iostream>
#include <memory>
#include <thread>

#include "latency_lines.hpp"
#include "window/brush_outline_overlay.hpp"
#include "window/canvas_menu.hpp"
#include "window/canvas_viewer.hpp"
#include "window/document.hpp"
#include "window/edit_help_menus.hpp"
#include "window/eyedropper.hpp"
#include "window/input_router.hpp"
#include "window/opening_note.hpp"
#include "window/paint_options.hpp"
#include "window/palette_board_panel.hpp"
#include "window/panels.hpp"
#include "window/pigment_drift_note.hpp"
#include "window/pigment_editor.hpp"
#include "window/pointer_latency.hpp"
#include "window/reference_image.hpp"
#include "window/session_banner.hpp"
#include "window/swatch_chips.hpp"
#include "window/timelapse_export.hpp"
#include "window/tool_bar.hpp"
#include "window/window_shell.hpp"
#include "window/window_title.hpp"

namespace impasto::app::window {
namespace {

using Clock = std::chrono::steady_clock;

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
// How long a frame waits for the simulation to apply the pen samples it has just submitted:
// shown by this frame instead of the next, they reach the screen a frame sooner, and the
// simulation has its own core meanwhile.
constexpr auto kSimWait = std::chrono::milliseconds(15);

class PaintWindow {
 public:
  explicit PaintWindow(const PaintOptions& options);
  void run();

 private:
  void draw_frame(bool take_screenshot);
  // A frame's canvas, shaded as the view's motion and the canvas's changes allow, and shown.
  void draw_canvas(int fb_w, int fb_h, int win_w, bool take_screenshot);
  void time_view_motion(double swap_time_s);
  // The painting was replaced (new, open, recovered, reframed): the view and quality restart.
  void painting_replaced() {
    viewer_->painting_replaced();
    router_->painting_replaced();
  }
  void report_latency() const;
  session::SimWorker& worker() { return document_->worker(); }

  // Members are destroyed in reverse: the tablets' threads first, the GL context last.
  PaintOptions options_;
  WindowState state_;
  WindowShell shell_;
  double session_start_s_;
  ViewLatency view_latency_;  // a zoom step's, rotation's, pan's or light's event -> the swap
  std::array<double, 2> shown_light_{};  // the light's direction at the last swap
  std::vector<int> coarse_factors_;      // of each coarse frame, for the report
  std::uint64_t applied_at_upload_ = 0;  // simulation jobs applied before this frame's upload
  bool frame_changed_ = true;            // the last frame re-shaded some of the canvas
  // The first frames: the panels and a note (opening_note.hpp) until the palette's own rule is
  // built, for at most kRuleWait_s (the view is then shaded whole once, not twice).
  bool opening_ = true;
  PaletteBoardPanel board_panel_;
  PigmentEditor pigment_editor_;
  CanvasMenu canvas_menu_;
  TimelapseExport timelapse_;  // File > Export time-lapse... and the video being written
  ReferenceImage reference_;   // View > Reference image...
  ColourTarget colour_target_;
  PaintStrip paint_strip_;  // its palette and saved mixes
  PigmentDriftNote pigment_drift_;
  SwatchChips swatch_chips_;
  PointerOverlay pointer_overlay_;  // the brush's outline and the empty-brush note
  // The preview of a session offered for recovery, as a texture.
  std::unique_ptr<PreviewTexture> preview_ = std::make_unique<PreviewTexture>();
  std::unique_ptr<CanvasViewer> viewer_;  // the painting on the GPU and its shaded view
  // The painting and its session (after the panels: it opens the board beside the painting).
  std::unique_ptr<Document> document_;
  std::unique_ptr<InputRouter> router_;
};

PaintWindow::PaintWindow(const PaintOptions& options)
    : options_(options),
      state_(initial_window_state(options)),
      shell_(options.window_width, options.window_height, window_title(options.painting, false)),
      session_start_s_(shell_.now_s()) {
  document_ = std::make_unique<Document>(options_, state_, board_panel_);
  viewer_ = std::make_unique<CanvasViewer>(worker());
  router_ = std::make_unique<InputRouter>(shell_, state_, *document_, *viewer_, view_latency_,
                                          pointer_overlay_, session_start_s_);
}

// A frame was swapped at swap_time_s: it shows every view motion applied before it. The
// Light panel's disc moves the light as ImGui reads this frame's pointer events, so when the
// light's direction changed, those events moved it.
void PaintWindow::time_view_motion(double swap_time_s) {
  const std::array<double, 2> light = {state_.settings.light_azimuth_deg,
                                       state_.settings.light_elevation_deg};
  if (light != shown_light_) {
    for (const double t : router_->frame_pointer_times())
      view_latency_.submitted(ViewMotion::kLight, t);
    view_latency_.applied(ViewMotion::kLight);
  }
  shown_light_ = light;
  view_latency_.shown(swap_time_s);
  // A drag's move that arrives while a frame is drawn waits for it, then for its own frame:
  // the two fit the 100 ms.
  viewer_->set_moving(view_latency_.moving());
}

void PaintWindow::draw_frame(bool take_screenshot) {
  const auto start = Clock::now();
  if (worker().stats().submitted != applied_at_upload_) worker().wait_idle_for(kSimWait);
  applied_at_upload_ = worker().stats().applied;  // each has dirtied its tiles by now
  viewer_->sync(worker(), state_, router_->in_stroke(), shell_.now_s());
  // The Palette panel's chips, painted and rendered off the UI thread (swatch_chips.hpp),
  // under the painting's own rule (the viewer's, synced just now).
  const paintcore::CanvasSpec canvas_spec =
      worker().with_painting([](const paintcore::Painting& p) { return p.canvas().spec(); });
  swatch_chips_.update(state_, canvas_spec, viewer_->palette().sampling());
  int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
  shell_.framebuffer_size(fb_w, fb_h);
  shell_.window_size(win_w, win_h);
  if (state_.fit_requested && fb_w > 0) {
    // Fit into the part of the window left of the panels.
    state_.view = render_gl::fit_canvas(viewer_->width_cells(), viewer_->height_cells(),
                                        std::max(win_w - kPanelsWidth, 100), win_h - 60);
    // (shifted right of centre)
    state_.view.center_x_cells += 0.5 * kPanelsWidth / state_.view.pixels_per_cell;
    state_.fit_requested = false;
  }

  shell_.begin_ui_frame();
  const PaintingSnapshot painting = document_->snapshot();
  const FileActions files = document_->file_actions();
  PanelContext context{state_, worker(),     painting,      viewer_->palette(),
                       files,  board_panel_, colour_target_};
  draw_panels(context);
  draw_tool_bar(state_, worker(), painting.brush_volume_mm3, paint_strip_);
  draw_session_banners(worker().stats(), document_->notice());
  pigment_editor_.draw(state_, viewer_->palette());
  const CanvasMenuRequest canvas_request =
      canvas_menu_.draw(viewer_->width_cells(), viewer_->height_cells(), state_.file);
  timelapse_.draw(state_, *document_, viewer_->width_cells(), viewer_->height_cells());
  reference_.draw(state_, colour_target_);
  if (ImGui::BeginMainMenuBar()) {  // Help, last on the menu bar
    help_menu(state_);
    ImGui::EndMainMenuBar();
  }
  draw_help_windows(state_);
  double cursor_x = 0, cursor_y = 0;
  shell_.cursor(cursor_x, cursor_y);
  if (router_->pick_cursor()) {
    draw_pick_cursor(state_, static_cast<float>(cursor_x), static_cast<float>(cursor_y));
  } else {
    pointer_overlay_.draw(painting, state_.mouse_pressure, state_.view, win_w, win_h, cursor_x,
                          cursor_y, shell_.now_s(), router_->tablet_pen());
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
  if (opening) {
    shell_.present_over_background(state_.view_options.background_rgb);
    opening_ = viewer_->palette_stands_in() && shell_.now_s() - session_start_s_ < kRuleWait_s;
    frame_changed_ = false;  // the loop idles between these frames: the rule has the cores
  } else {
    draw_canvas(fb_w, fb_h, win_w, take_screenshot);
  }
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

void PaintWindow::draw_canvas(int fb_w, int fb_h, int win_w, bool take_screenshot) {
  // The view is in window coordinates; scale it to framebuffer pixels (HiDPI).
  render_gl::CanvasView fb_view = state_.view;
  const double fb_scale = win_w > 0 ? static_cast<double>(fb_w) / win_w : 1.0;
  fb_view.pixels_per_cell *= fb_scale;
  const render_gl::CachedDrawStats canvas =
      viewer_->shade(state_, fb_view, fb_w, fb_h, take_screenshot, router_->in_stroke(),
                     shell_.now_s(), router_->tip_down_s());
  state_.pixels_shaded += canvas.pixels_shaded;
  frame_changed_ = !canvas.changed.empty();
  shell_.present(canvas.changed, state_.ui_textures_changed, fb_scale,
                 take_screenshot ? &*options_.screenshot : nullptr,
                 [this](const render_gl::PixelRect& rect) { viewer_->copy_to(0, rect); });
  state_.ui_textures_changed.clear();
  InputLatency& latency = router_->latency();
  latency.shown(applied_at_upload_, shell_.now_s() - session_start_s_);
  time_view_motion(shell_.now_s());
  if (canvas.coarse) coarse_factors_.push_back(canvas.coarse_factor);
  state_.input_latency_ms = latency.recent_median_ms().value_or(-1.0);
  state_.input_latency_p95_ms = latency.recent_percentile_ms(0.95).value_or(-1.0);
  state_.input_behind_ms = latency.behind_ms(shell_.now_s() - session_start_s_);
}

void PaintWindow::run() {
  int frames_since_idle = 0;
  bool screenshot_done = !options_.screenshot;
  bool replay_shown = false;
  WindowShell::close_on_signals();
  bool terminated = false;
  while (!state_.quit) {
    if (WindowShell::signalled()) {
      terminated = true;
      break;
    }
    shell_.poll();
    if (shell_.take_close_request()) {
      if (options_.exit_after) break;
      // As File > Quit: with unsaved changes, Save / Discard / Cancel.
      state_.commands.push_back(Command::kQuit);
    }
    if (document_->run_pending_action()) painting_replaced();
    // A time-lapse being written asks before it is stopped (its dialog sets quit again).
    if (state_.quit && !timelapse_.allow_quit()) state_.quit = false;
    if (state_.quit) break;
    shell_.set_title(window_title(state_.file, worker().stats().events_since_save > 0));
    router_->route();
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
    if (!router_->in_stroke() && worker().idle()) viewer_->make_room();
    if (capture) {
      screenshot_done = true;
      std::cout << "wrote " << options_.screenshot->string() << "\n";
    }
    // A script driving the window (impasto bench window) waits for this line, not a guess.
    if (options_.replay && !replay_shown && frames_since_idle >= 3) {
      replay_shown = true;
      std::cout << "replayed: " << options_.replay->string() << " is on screen" << std::endl;
    }
    document_->maybe_autosave(shell_.now_s(), router_->in_stroke());
    document_->note_recording_failure();
    if (options_.exit_after && screenshot_done && worker().idle()) break;
  }
  report_latency();
  document_->close(terminated);
}

// The session's input latency, for measuring it (docs/measurements/window.md, "Latency").
void PaintWindow::report_latency() const {
  std::cout << view_latency_.report(coarse_factors_);
  const InputLatency& latency = router_->latency();
  if (latency.shown_count() == 0) return;
  std::cout << latency_line("input", "pen event", "samples",
                            {*latency.percentile_ms(0.5), *latency.percentile_ms(0.95),
                             static_cast<int>(latency.shown_count())})
            << "; " << shell_.server_timed() << " mouse events timed by the window system, "
            << shell_.delivery_timed() << " when delivered\n";
}

}  // namespace

void run_paint_window(const PaintOptions& options) {
  PaintWindow window(options);
  window.run();
}

}  // namespace impasto::app::window
