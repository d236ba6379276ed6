#pragma once
// The window's input router: each frame it turns what the shell gathered (mouse events with
// their own times, key presses, wheel clicks) and the tablets' samples into pen samples for
// the simulation, view motions, eyedropper picks and commands, in the order they came. A
// stroke's samples go through one pen feed; a brush change asked mid-stroke waits for it to end.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/pen_feed.hpp"
#include "window/brush_outline_overlay.hpp"
#include "window/canvas_viewer.hpp"
#include "window/document.hpp"
#include "window/eyedropper.hpp"
#include "window/pointer_gestures.hpp"
#include "window/pointer_latency.hpp"
#include "window/tablets.hpp"
#include "window/window_shell.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class InputRouter {
 public:
  // `session_start_s`: the shell's clock when the session began (pen samples' time zero).
  InputRouter(WindowShell& shell, WindowState& state, Document& document, CanvasViewer& viewer,
              ViewLatency& view_latency, PointerOverlay& overlay, double session_start_s);

  // This frame's input: keys and the commands waiting, the tablets, then the mouse.
  void route();

  bool in_stroke() const { return feed_.in_stroke(); }
  // Each pen sample from its own time to the swap that shows it.
  InputLatency& latency() { return latency_; }
  const InputLatency& latency() const { return latency_; }
  double tip_down_s() const { return tip_down_s_; }  // the last sample with the tip down
  // This frame's presses and moves (what moved the light, when the Light panel's disc did).
  const std::vector<double>& frame_pointer_times() const { return frame_pointer_times_; }
  bool pick_cursor() const { return pick_cursor_; }  // the eyedropper would pick here
  // The newest sample of a tablet's pen that is near (hovering or pressed), else nullptr.
  const paintcore::PenSample* tablet_pen() const;
  // A new painting steps at the chosen quality from its first sample (its file may hold any).
  void painting_replaced() { sent_quality_.reset(); }

 private:
  void route_keys();
  void run_commands();
  void route_pointer();
  void zoom_with_wheel(double x, double y);
  void pick_at(const PointerEvent& at, bool released);
  void pen_sample(const PointerEvent& at, bool tip_down);
  void pan_view(double from_x, double from_y, double to_x, double to_y, double time_s);
  void rotate_view(double from_x, double from_y, double to_x, double to_y, double time_s);
  void submit_pen_event(input::StrokeEvent event);
  // Before a pen sample: the quality the simulation should step it at, told when it changes.
  void choose_quality(double now_s);
  TabletTargetGeometry tablet_geometry() const;
  session::SimWorker& worker() { return document_.worker(); }

  WindowShell& shell_;
  WindowState& state_;
  Document& document_;
  CanvasViewer& viewer_;
  ViewLatency& view_latency_;
  PointerOverlay& overlay_;
  double session_start_s_;
  int window_w_ = 0, window_h_ = 0;  // this frame's window size

  // Every pen sample, mouse or tablet, goes to the simulation through this feed.
  session::PenFeed feed_{[this](input::StrokeEvent event) { submit_pen_event(std::move(event)); }};
  InputLatency latency_;
  double tip_down_s_ = -1e9;
  std::vector<double> frame_pointer_times_;
  PointerGestures gestures_{{
      [this](const PointerEvent& at, bool tip_down) { pen_sample(at, tip_down); },
      [this](double fx, double fy, double tx, double ty, double t) { pan_view(fx, fy, tx, ty, t); },
      [this](double fx, double fy, double tx, double ty, double t) {
        rotate_view(fx, fy, tx, ty, t);
      },
  }};
  SpeedPressure speed_pressure_;
  PickGesture pick_gesture_;  // the eyedropper's presses on the canvas
  bool pick_cursor_ = false;
  std::string head_before_knife_ = "round";  // where B returns to from the knife (K)
  std::unique_ptr<Tablets> tablets_;         // read on their own threads, polled once a frame
  CatchUp catch_up_;
  std::optional<paintcore::StepQuality> sent_quality_;  // the last quality record submitted
};

}  // namespace impasto::app::window
