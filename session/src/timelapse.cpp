#include "impasto/session/timelapse.hpp"

#include <impasto/render/spectral_palette.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "impasto/files/memory_budget.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/session/kept_origin.hpp"

namespace impasto::session {

namespace {

const paintcore::PenSample* sample_of(const input::StrokeEvent& event) {
  const auto* sample = std::get_if<input::SampleEvent>(&event);
  return sample != nullptr ? &sample->sample : nullptr;
}

// The first and last sample times, and how many samples there are.
struct SessionClock {
  double first_s = 0.0, last_s = 0.0;
  std::size_t samples = 0;
};

SessionClock session_clock(const input::StrokeFile& file) {
  SessionClock clock;
  for (const input::StrokeEvent& event : file.events) {
    const paintcore::PenSample* sample = sample_of(event);
    if (sample == nullptr) continue;
    if (clock.samples == 0) clock.first_s = sample->time_s;
    clock.last_s = std::max(clock.last_s, sample->time_s);
    ++clock.samples;
  }
  return clock;
}

void check_options(const TimelapseOptions& options) {
  if (!(options.fps > 0.0 && options.fps <= 240.0))
    throw std::runtime_error("time-lapse: --fps must be in (0, 240]");
  if (!(options.growth_seconds > 0.0 && options.growth_seconds <= 3600.0))
    throw std::runtime_error("time-lapse: --seconds must be in (0, 3600]");
  if (!(options.hold_seconds >= 0.0 && options.hold_seconds <= 600.0))
    throw std::runtime_error("time-lapse: --hold must be in [0, 600] seconds");
  if (options.shade_scale < 1 || options.shade_scale > 4)
    throw std::runtime_error("time-lapse: the shading scale must be 1..4");
}

// The canvas rendered incrementally: the tiles changed since the last frame are re-shaded; a
// new pigment slot (the palette grows) or a turned light re-shades everything.
class FrameRenderer {
 public:
  FrameRenderer(render::RenderSettings settings, int shade_scale)
      : settings_(std::move(settings)), shade_scale_(shade_scale) {}

  const render::Image& render(paintcore::Painting& painting, double azimuth_deg) {
    const paintcore::Canvas& canvas = painting.canvas();
    if (changes_.id < 0) changes_ = painting.subscribe_changes();
    const std::vector<int> changed = paintcore::tile_indices(painting.take_changes(changes_));
    const bool turned = azimuth_deg != settings_.light_azimuth_deg;
    settings_.light_azimuth_deg = azimuth_deg;
    if (shade_scale_ > 1 && canvas.cracks().empty()) {
      // The relief refined to the frame's size: a whole render of each frame that changed.
      if (image_.rgb.empty() || turned || !changed.empty())
        image_ = render::render_painting(painting.refined(shade_scale_), settings_);
      return image_;
    }
    if (!renderer_ || painting.slot_count() != slots_) {
      palette_.emplace(settings_, painting);
      renderer_.emplace(settings_, *palette_);
      slots_ = painting.slot_count();
      renderer_->render_all(canvas);
    } else if (turned) {
      renderer_->set_settings(settings_, *palette_);
      renderer_->render_all(canvas);
    } else {
      renderer_->update(canvas, changed);
    }
    image_ = renderer_->image();
    return image_;
  }

 private:
  render::RenderSettings settings_;
  int shade_scale_ = 1;
  std::optional<render::SpectralPalette> palette_;
  std::optional<render::TileRenderer> renderer_;
  int slots_ = -1;
  paintcore::Painting::ChangeSubscriber changes_;  // subscribed on the first frame
  render::Image image_;
};

// The painting the session began from (kept_origin.hpp), with the constants it was painted
// with, as the window painted on it; a blank canvas for a new one, or when a canvas is forced.
paintcore::Painting start_painting(const input::StrokeFile& file, const ReplayOptions& replay,
                                   TimelapseReport& report) {
  const bool forced = replay.width_cells || replay.height_cells || replay.dpi;
  if (!forced) {
    std::optional<paintcore::Painting> origin =
        load_session_origin(file, replay.threads, report.warnings);
    if (origin) {
      report.base = "the painting the session began from";
      return std::move(*origin);
    }
  }
  paintcore::Painting painting(replay_canvas(file, replay), replay.threads);
  painting.set_params(replay_params(replay));
  return painting;
}

}  // namespace

int timelapse_shade_scale(const paintcore::CanvasSpec& canvas, int frame_width, int frame_height) {
  int scale = 1;
  while (scale < 4 && (static_cast<long>(canvas.width_cells) * scale < frame_width ||
                       static_cast<long>(canvas.height_cells) * scale < frame_height))
    ++scale;
  return scale;
}

int timelapse_growth_frames(const input::StrokeFile& file, const TimelapseOptions& options) {
  check_options(options);
  const SessionClock clock = session_clock(file);
  const double seconds =
      options.real_time ? std::min(clock.last_s - clock.first_s, 3600.0) : options.growth_seconds;
  return std::max(1, static_cast<int>(std::ceil(seconds * options.fps - 1e-9)));
}

TimelapseReport play_timelapse(const input::StrokeFile& file, const ReplayOptions& replay,
                               const TimelapseOptions& options,
                               const std::function<void(const render::Image&)>& frame) {
  TimelapseReport report;
  report.growth_frames = timelapse_growth_frames(file, options);
  report.hold_frames = static_cast<int>(std::lround(options.hold_seconds * options.fps));
  const int frames = report.growth_frames + report.hold_frames;
  const SessionClock clock = session_clock(file);

  paintcore::Painting painting = start_painting(file, replay, report);
  render::check_render_memory(painting.canvas(), file.source);
  SessionPlayer player(painting, replay, replay.auto_load && !has_load_record(file));
  FrameRenderer renderer(options.settings, options.shade_scale);
  const double azimuth0 = options.settings.light_azimuth_deg;
  const auto azimuth_at = [&](int index) {
    if (!options.light_azimuth_end_deg || frames < 2) return azimuth0;
    return azimuth0 + (*options.light_azimuth_end_deg - azimuth0) * index / (frames - 1);
  };

  std::size_t next = 0, samples_done = 0;
  const auto apply_next = [&] {
    try {
      player.apply(file.events[next]);
    } catch (const std::exception& e) {
      throw std::runtime_error(file.where(next) + ": " + files::error_text(e));
    }
    if (sample_of(file.events[next]) != nullptr) ++samples_done;
    ++next;
  };
  for (int k = 1; k <= report.growth_frames; ++k) {
    if (k == report.growth_frames) {
      while (next < file.events.size()) apply_next();
      player.finish();
    } else if (options.real_time) {
      const double until = clock.first_s + k / options.fps;
      while (next < file.events.size()) {
        const paintcore::PenSample* sample = sample_of(file.events[next]);
        if (sample != nullptr && sample->time_s > until) break;
        apply_next();
      }
    } else {
      // The samples so far: k / growth_frames of them (the events between come with them).
      const auto wanted = static_cast<std::size_t>(
          std::ceil(static_cast<double>(clock.samples) * k / report.growth_frames));
      while (next < file.events.size() &&
             (samples_done < wanted || sample_of(file.events[next]) == nullptr))
        apply_next();
    }
    frame(renderer.render(painting, azimuth_at(k - 1)));
    if (options.progress) options.progress(static_cast<std::size_t>(k), frames);
  }
  report.replay = player.report();
  for (int h = 0; h < report.hold_frames; ++h) {
    const int index = report.growth_frames + h;
    frame(renderer.render(painting, azimuth_at(index)));
    if (options.progress) options.progress(static_cast<std::size_t>(index + 1), frames);
  }
  return report;
}

}  // namespace impasto::session
