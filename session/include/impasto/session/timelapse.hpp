#pragma once
// A painting session's growth as frames: the stroke file replayed as `impasto replay` does
// (bit-exactly), the canvas rendered at evenly spaced moments of it, each frame re-shading
// only the tiles the strokes since the last one changed, then the finished painting held.
// The light may turn over the video (every frame then re-shades the whole canvas).
#include <impasto/input/stroke_events.hpp>
#include <impasto/render/image.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/util/progress.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/replay.hpp"

namespace impasto::session {

struct TimelapseOptions {
  double fps = 30.0;
  // The session's pen samples spread evenly over this many seconds...
  double growth_seconds = 10.0;
  // ...or, when set, at the session's own pace (its samples' times; pauses kept).
  bool real_time = false;
  double hold_seconds = 2.0;  // the finished painting, held at the end
  render::RenderSettings settings;
  // The light's azimuth at the last frame: it turns from settings.light_azimuth_deg to this
  // over the video, evenly. Unset: a still light.
  std::optional<double> light_azimuth_end_deg;
  // The relief shaded on a canvas this many times finer (1..4; Painting::refined, as `export
  // --scale` does), for a video larger than the canvas: its frames show the relief at their
  // own size, not the canvas's cells enlarged. Each frame that changed is then a whole
  // render, about scale² times a canvas render's cost. A cracked painting is shaded at its
  // cells (the finer canvas does not carry cracks).
  int shade_scale = 1;
  // Hears of each frame made, of all.
  util::ProgressCallback progress;
};

struct TimelapseReport {
  // What the first frame's painting is: a blank canvas, or the painting the session began
  // from (kept_origin.hpp). Why the latter could not be had is in warnings.
  std::string base = "a blank canvas";
  std::vector<std::string> warnings;
  int growth_frames = 0;
  int hold_frames = 0;
  ReplayReport replay;
};

// The shade_scale a video of frame_width x frame_height pixels asks of `canvas`: the smallest
// whole scale at which the canvas has as many cells as the frame has pixels, at most 4.
int timelapse_shade_scale(const paintcore::CanvasSpec& canvas, int frame_width, int frame_height);

// How many frames show the growth: fps × growth_seconds, or fps × the session's length in
// real time; at least one.
int timelapse_growth_frames(const input::StrokeFile& file, const TimelapseOptions& options);

// Replays `file` with `replay` (its canvas, brush and constants) over the painting the
// session began from (a blank canvas for a new one, or when `replay` forces a canvas), and hands
// each frame, in order, to `frame` (display-encoded RGB at the canvas's cells times shade_scale).
// Throws std::runtime_error naming the record ("FILE:LINE: ...") that cannot be applied; no frame
// follows it.
TimelapseReport play_timelapse(const input::StrokeFile& file, const ReplayOptions& replay,
                               const TimelapseOptions& options,
                               const std::function<void(const render::Image&)>& frame);

}  // namespace impasto::session
