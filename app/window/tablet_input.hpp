#pragma once
// Pen tablets in the painting window: where the tablet's active area lands (the whole
// screen, the window, or the whole canvas), the pressure curve, and the mapping of each
// tablet sample (tablet mm) to a canvas sample (canvas mm) through the canvas view, as the
// mouse's window pixels are mapped.
#include <impasto/input/hid_device.hpp>
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/tablet_mapping.hpp>
#include <impasto/paintcore/pen_sample.hpp>
#include <impasto/render_gl/canvas_view.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>

#include "impasto/session/pen_feed.hpp"

namespace impasto::app::window {

enum class TabletTarget {
  kScreen,  // the tablet is the whole monitor (as a tablet driver maps it)
  kWindow,  // the tablet is the window
  kCanvas,  // the tablet is the whole canvas, whatever the view
};

struct TabletSettings {
  TabletTarget target = TabletTarget::kWindow;
  bool keep_aspect = true;  // use the largest part of the tablet with the target's shape
  bool bezier = false;      // the pressure curve: p^gamma, or a Bezier (as drivers draw it)
  float pressure_gamma = 1.0f;
  std::array<float, 4> bezier_points{0.25f, 0.25f, 0.75f, 0.75f};  // x1, y1, x2, y2

  input::PressureCurve pressure_curve() const;
};

// Where things are this frame. Pixels are window coordinates (y down), as GLFW reports the
// cursor and as CanvasView::window_to_cell takes them.
struct TabletTargetGeometry {
  input::Rect screen_px;           // the monitor, in screen coordinates
  input::Point window_origin_px;   // the window's top-left corner, in screen coordinates
  int window_w = 0, window_h = 0;  // the window's size
  render_gl::CanvasView view;      // the canvas view in that window
  int canvas_w_cells = 0, canvas_h_cells = 0;
  double cell_mm = 0.1;
};

// The sample at its canvas position (mm) with its pressure through the curve; tilt,
// rotation, buttons and time unchanged. Throws std::invalid_argument for an empty area or
// target (a tablet that reports no size, a minimised window).
paintcore::PenSample map_tablet_sample(const paintcore::PenSample& tablet_sample,
                                       const input::hid::TabletArea& area,
                                       const TabletSettings& settings,
                                       const TabletTargetGeometry& geometry);

// What the window does with each frame's tablet samples, oldest first by their own times
// (several tablets interleaved): every sample mapped with its own tablet's area, its time
// moved onto the session clock (+ time_offset_s), and fed. A sample that cannot be mapped is
// skipped and its reason left in *error; the newest fed is left in *newest. Returns the
// samples fed.
std::size_t feed_tablet_samples(std::span<const input::hid::TabletSamples> polled,
                                double time_offset_s, const TabletSettings& settings,
                                const TabletTargetGeometry& geometry, session::PenFeed& feed,
                                std::string* error = nullptr,
                                paintcore::PenSample* newest = nullptr);

}  // namespace impasto::app::window
