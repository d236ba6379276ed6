#include "window/tablet_input.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace impasto::app::window {

input::PressureCurve TabletSettings::pressure_curve() const {
  if (bezier) {
    return input::PressureCurve::bezier(bezier_points[0], bezier_points[1], bezier_points[2],
                                        bezier_points[3]);
  }
  return input::PressureCurve::gamma(pressure_gamma);
}

paintcore::PenSample map_tablet_sample(const paintcore::PenSample& tablet_sample,
                                       const input::hid::TabletArea& area,
                                       const TabletSettings& settings,
                                       const TabletTargetGeometry& geometry) {
  const input::Rect tablet{0.0, 0.0, area.width_mm, area.height_mm};
  paintcore::PenSample sample = tablet_sample;
  sample.pressure = static_cast<float>(
      settings.pressure_curve().apply(std::clamp(static_cast<double>(sample.pressure), 0.0, 1.0)));
  if (settings.target == TabletTarget::kCanvas) {
    const input::Rect canvas_mm{0.0, 0.0, geometry.canvas_w_cells * geometry.cell_mm,
                                geometry.canvas_h_cells * geometry.cell_mm};
    const input::Point p =
        input::AreaMapping(tablet, canvas_mm, settings.keep_aspect).map(sample.x_mm, sample.y_mm);
    sample.x_mm = p.x;
    sample.y_mm = p.y;
    return sample;
  }
  // Screen or window: to window pixels, then through the view as the mouse goes.
  const input::Rect window_on_screen{geometry.window_origin_px.x, geometry.window_origin_px.y,
                                     static_cast<double>(geometry.window_w),
                                     static_cast<double>(geometry.window_h)};
  const input::Rect target =
      settings.target == TabletTarget::kScreen ? geometry.screen_px : window_on_screen;
  const input::Point on_screen =
      input::AreaMapping(tablet, target, settings.keep_aspect).map(sample.x_mm, sample.y_mm);
  const auto cell = geometry.view.window_to_cell(on_screen.x - window_on_screen.x,
                                                 on_screen.y - window_on_screen.y,
                                                 geometry.window_w, geometry.window_h);
  sample.x_mm = cell[0] * geometry.cell_mm;
  sample.y_mm = cell[1] * geometry.cell_mm;
  return sample;
}

std::size_t feed_tablet_samples(std::span<const input::hid::TabletSamples> polled,
                                double time_offset_s, const TabletSettings& settings,
                                const TabletTargetGeometry& geometry, session::PenFeed& feed,
                                std::string* error, paintcore::PenSample* newest) {
  // Several tablets' samples interleaved by their own times (each tablet's order kept), so
  // the feed never has to hold a time back.
  struct Timed {
    const paintcore::PenSample* sample;
    const input::hid::TabletSamples* tablet;
  };
  std::vector<Timed> all;
  for (const input::hid::TabletSamples& tablet : polled) {
    for (const paintcore::PenSample& sample : tablet.samples) all.push_back({&sample, &tablet});
  }
  std::stable_sort(all.begin(), all.end(), [](const Timed& a, const Timed& b) {
    return a.sample->time_s < b.sample->time_s;
  });
  const std::size_t before = feed.fed();
  for (const Timed& timed : all) {
    paintcore::PenSample sample = *timed.sample;
    sample.time_s += time_offset_s;
    try {
      const paintcore::PenSample mapped =
          map_tablet_sample(sample, timed.tablet->tablet.area, settings, geometry);
      feed.feed(mapped);
      if (newest) *newest = mapped;
    } catch (const std::invalid_argument& e) {
      if (error) *error = timed.tablet->tablet.name + ": " + e.what();
    }
  }
  return feed.fed() - before;
}

}  // namespace impasto::app::window
