#pragma once
// A recorded session's time-lapse written as a video file: the frames of
// session::play_timelapse encoded by VideoWriter. The command line's `impasto timelapse` and
// the window's File > Export time-lapse... both write through it.
#include <impasto/input/stroke_events.hpp>

#include <filesystem>
#include <optional>
#include <string>

#include "impasto/session/timelapse.hpp"
#include "vocabulary_words.hpp"

namespace impasto::app {

struct TimelapseVideo {
  session::TimelapseReport report;
  int width = 0, height = 0, frames = 0;
};

// Writes the video to `out` (atomically: a failure, or an exception thrown from
// options.progress to stop, leaves no file). `frame_size`: the video's pixels (rounded down
// to even); none: the canvas's cells. A frame larger than the canvas is shaded at its own
// size (the shade scale timelapse_shade_scale gives).
TimelapseVideo write_timelapse_video(const input::StrokeFile& file,
                                     const session::ReplayOptions& replay,
                                     const session::TimelapseOptions& options,
                                     const std::filesystem::path& out,
                                     const std::optional<CanvasSize>& frame_size);

// "wrote FILE (WxH, N frames at F fps: G of the growth of S strokes over B, H of the finished
// painting)".
std::string timelapse_summary(const TimelapseVideo& video, const std::filesystem::path& out,
                              double fps);

}  // namespace impasto::app
