#include "timelapse_video.hpp"

#include <cstdio>

#include "video_writer.hpp"

namespace impasto::app {

TimelapseVideo write_timelapse_video(const input::StrokeFile& file,
                                     const session::ReplayOptions& replay,
                                     const session::TimelapseOptions& options,
                                     const std::filesystem::path& out,
                                     const std::optional<CanvasSize>& frame_size) {
  (void)video_kind(out);  // a bad extension fails now, not after the replay
  const paintcore::CanvasSpec canvas = session::replay_canvas(file, replay);
  const int width = frame_size ? frame_size->width : canvas.width_cells;
  const int height = frame_size ? frame_size->height : canvas.height_cells;
  VideoWriter video(out, width, height, options.fps);
  session::TimelapseOptions shaded = options;
  shaded.shade_scale = session::timelapse_shade_scale(canvas, video.width(), video.height());
  TimelapseVideo written;
  written.report = session::play_timelapse(
      file, replay, shaded, [&video](const render::Image& frame) { video.add_frame(frame); });
  video.finish();
  written.width = video.width();
  written.height = video.height();
  written.frames = video.frames();
  return written;
}

std::string timelapse_summary(const TimelapseVideo& video, const std::filesystem::path& out,
                              double fps) {
  char summary[400];
  std::snprintf(summary, sizeof summary,
                "wrote %s (%dx%d, %d frames at %g fps: %d of the growth of %llu strokes over %s, "
                "%d of the finished painting)",
                out.string().c_str(), video.width, video.height, video.frames, fps,
                video.report.growth_frames,
                static_cast<unsigned long long>(video.report.replay.strokes),
                video.report.base.c_str(), video.report.hold_frames);
  return summary;
}

}  // namespace impasto::app
