#include "window/input_router.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <impasto/input/stroke_import.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "window/shortcuts.hpp"

namespace impasto::app::window {
namespace {

// A wheel notch zooms by a quarter, as image editors do: five notches are about 3x.
constexpr double kZoomPerWheelNotch = 1.25;

// A stroke begun with nothing on the brush paints nothing: say so where the pointer is, once a
// session (only when every event is applied, so a Load brush still queued is not missed).
void note_an_empty_brush(session::SimWorker& worker, PointerOverlay& overlay, double now_s) {
  if (!worker.idle()) return;
  overlay.stroke_began(
      worker.with_painting([](const paintcore::Painting& p) { return p.brush_totals().volume; }),
      now_s);
}

}  // namespace

InputRouter::InputRouter(WindowShell& shell, WindowState& state, Document& document,
                         CanvasViewer& viewer, ViewLatency& view_latency, PointerOverlay& overlay,
                         double session_start_s)
    : shell_(shell),
      state_(state),
      document_(document),
      viewer_(viewer),
      view_latency_(view_latency),
      overlay_(overlay),
      session_start_s_(session_start_s),
      tablets_(std::make_unique<Tablets>(shell.now_s() - session_start_s, state)) {}

void InputRouter::route() {
  route_keys();
  tablets_->poll(
      state_, [this] { return tablet_geometry(); }, feed_, shell_.now_s());
  route_pointer();
  // The status bar says so while a sample taken at fast steps is still on its way.
  state_.catching_up =
      catch_up_.catching_up() && latency_.behind_ms(shell_.now_s() - session_start_s_) > 0.0;
}

TabletTargetGeometry InputRouter::tablet_geometry() const {
  TabletTargetGeometry geometry;
  shell_.window_size(geometry.window_w, geometry.window_h);
  const std::array<double, 2> origin = shell_.window_origin_px();
  const std::array<double, 4> screen = shell_.screen_px();
  geometry.window_origin_px = {origin[0], origin[1]};
  geometry.screen_px = {screen[0], screen[1], screen[2], screen[3]};
  geometry.view = state_.view;
  geometry.canvas_w_cells = viewer_.width_cells();
  geometry.canvas_h_cells = viewer_.height_cells();
  geometry.cell_mm = viewer_.cell_mm();
  return geometry;
}

void InputRouter::pen_sample(const PointerEvent& at, bool tip_down) {
  const auto cell = state_.view.window_to_cell(at.x, at.y, window_w_, window_h_);
  const double cell_mm = viewer_.cell_mm();
  paintcore::PenSample sample;
  sample.time_s = at.time_s - session_start_s_;  // the event's own time
  sample.x_mm = cell[0] * cell_mm;
  sample.y_mm = cell[1] * cell_mm;
  if (tip_down && !feed_.in_stroke()) {
    speed_pressure_.start_stroke();
    note_an_empty_brush(worker(), overlay_, shell_.now_s());
  }
  const float pressure = state_.pressure_from_speed
                             ? speed_pressure_.at(sample.x_mm, sample.y_mm, sample.time_s)
                             : state_.mouse_pressure;
  sample.pressure = tip_down ? pressure : 0.0f;
  sample.buttons = paintcore::kPenInRange | (tip_down ? paintcore::kPenTip : 0u);
  feed_.feed(sample);
}

void InputRouter::submit_pen_event(input::StrokeEvent event) {
  const auto* sample = std::get_if<input::SampleEvent>(&event);
  const double time_s = sample ? sample->sample.time_s : 0.0;
  if (sample) choose_quality(shell_.now_s());
  worker().submit(std::move(event));
  const double now = shell_.now_s();
  document_.note_input(now);
  // Only this thread submits, so the count just read is this event's job number.
  if (sample) latency_.submitted(worker().stats().submitted, time_s);
  if (sample && (sample->sample.buttons & paintcore::kPenTip) != 0) tip_down_s_ = now;
}

// Each change of quality is a record in the session, so a replay steps as the window did.
void InputRouter::choose_quality(double now_s) {
  const paintcore::StepQuality wanted =
      catch_up_.next(state_.quality, state_.catch_up, latency_.behind_ms(now_s - session_start_s_));
  if (sent_quality_ == wanted) return;
  worker().submit(input::QualityEvent{wanted});
  sent_quality_ = wanted;
}

void InputRouter::pan_view(double from_x, double from_y, double to_x, double to_y, double time_s) {
  const auto a = state_.view.window_to_cell(from_x, from_y, window_w_, window_h_);
  const auto b = state_.view.window_to_cell(to_x, to_y, window_w_, window_h_);
  state_.view.center_x_cells -= b[0] - a[0];
  state_.view.center_y_cells -= b[1] - a[1];
  view_latency_.submitted(ViewMotion::kPan, time_s);
  view_latency_.applied(ViewMotion::kPan);
}

void InputRouter::rotate_view(double from_x, double from_y, double to_x, double to_y,
                              double time_s) {
  const double a0 = std::atan2(from_y - window_h_ / 2.0, from_x - window_w_ / 2.0);
  const double a1 = std::atan2(to_y - window_h_ / 2.0, to_x - window_w_ / 2.0);
  state_.view.rotation_rad += a1 - a0;
  view_latency_.submitted(ViewMotion::kRotate, time_s);
  view_latency_.applied(ViewMotion::kRotate);
}

// Applies every mouse event since the last frame in order: each move of a stroke is a pen
// sample with its own time, and each press and release starts or ends its drag where it
// happened.
void InputRouter::route_pointer() {
  shell_.window_size(window_w_, window_h_);
  // The wheel clicks since the last frame, each timed from its own event.
  for (const double t : shell_.take_wheel_times()) view_latency_.submitted(ViewMotion::kZoom, t);
  PointerFrame frame;
  frame.space_down = shell_.key_down(GLFW_KEY_SPACE);
  // While a tablet's pen is near, it paints: it moves the cursor and presses the button
  // too, and its own samples carry the real pressure.
  frame.tablet_near = tablets_->near(shell_.now_s());
  frame.canvas_at = [](double x, double y) { return !ui_at(x, y); };
  // The eyedropper (its tool, or Alt held) takes left presses on the canvas; a stroke under
  // way goes on to its end.
  const bool alt = shell_.key_down(GLFW_KEY_LEFT_ALT) || shell_.key_down(GLFW_KEY_RIGHT_ALT);
  const bool picking = (state_.eyedropper.tool || alt) && !gestures_.painting();
  const std::vector<PointerEvent> events = pick_gesture_.take_picks(
      shell_.take_pointer_events(), picking, frame.canvas_at,
      [this](const PointerEvent& at, bool released) { pick_at(at, released); });
  gestures_.apply(events, frame);
  frame_pointer_times_.clear();
  for (const PointerEvent& event : events) {
    if (event.action != PointerAction::kRelease) frame_pointer_times_.push_back(event.time_s);
  }

  double x = 0, y = 0;
  shell_.cursor(x, y);
  pick_cursor_ = pick_gesture_.held() || (picking && !ui_at(x, y));
  // (Asked here, between frames: within one, ImGui's implicit Debug window covers the canvas.)
  overlay_.set_on_canvas(!ui_at(x, y));
  shell_.set_crosshair(pick_cursor_);
  state_.cursor_cell = state_.view.window_to_cell(x, y, window_w_, window_h_);
  zoom_with_wheel(x, y);
}

// Keys become commands through the one table (shortcuts.hpp), unless a text field or a
// dialog or menu has the keyboard.
void InputRouter::route_keys() {
  const std::vector<KeyPress> keys = shell_.take_key_presses();
  if (!ui_has_keyboard()) {
    for (const KeyPress& press : keys) {
      if (const auto command = command_for_key(press.key, press.mods, press.repeat))
        state_.commands.push_back(*command);
    }
  }
  run_commands();
}

// Carries out what the keys and the menus asked for, in order; the file commands stay on the
// queue for the File menu, drawn later in this frame. A brush change waits for the stroke
// under way to end.
void InputRouter::run_commands() {
  std::vector<Command> waiting;
  const auto set_brush = [&](Command command, auto&& change) {
    if (feed_.in_stroke()) {
      waiting.push_back(command);
      return;
    }
    change();
    worker().submit(brush_event(state_));
  };
  for (const Command command : std::exchange(state_.commands, {})) {
    if (is_file_command(command)) {
      waiting.push_back(command);  // the File menu's, at this frame's panels
      continue;
    }
    paintcore::BrushSettings& brush = state_.brush;
    switch (command) {
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
          brush.size_mm = std::clamp(brush.size_mm * factor, kBrushSizeMinMm,
                                     paintcore::max_brush_size_mm(viewer_.cell_mm()));
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
      default:  // a file command: taken above
        break;
    }
  }
  state_.commands.insert(state_.commands.begin(), waiting.begin(), waiting.end());
}

// The eyedropper at a window position: the paint there is shown as the mouse moves; where
// the button is released it becomes the palette's mix and (load on pick) the brush's paint.
void InputRouter::pick_at(const PointerEvent& at, bool released) {
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
    render_picked_colours(*e.picked, state_.settings, viewer_.rule());
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

// Zooms about the cursor with the wheel, down to single cells and up to 64 px a cell.
void InputRouter::zoom_with_wheel(double x, double y) {
  const ImGuiIO& io = ImGui::GetIO();
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

const paintcore::PenSample* InputRouter::tablet_pen() const {
  return tablets_->pen(shell_.now_s());
}

}  // namespace impasto::app::window
