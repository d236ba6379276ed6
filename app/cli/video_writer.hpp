#pragma once
// A video file written frame by frame through Debian's libavcodec and libavformat: H.264 in
// MP4, VP9 in WebM or a GIF, chosen by the file's extension; yuv420p at an even size (GIF: 8
// colours' bits a pixel). Written atomically, as paintings are: the frames go to a temp file
// beside the target, which replaces it only when finish() succeeds.
#include <filesystem>
#include <memory>
#include <string>

#include "impasto/render/image.hpp"

namespace impasto::app {

enum class VideoKind { mp4, webm, gif };
// From the extension (.mp4, .webm, .gif, any case); throws std::runtime_error naming the file
// for another.
VideoKind video_kind(const std::filesystem::path& path);

class VideoWriter {
 public:
  // width and height are rounded down to even (yuv420p halves the colour's resolution), at
  // least 2 each; fps frames a second.
  VideoWriter(const std::filesystem::path& path, int width, int height, double fps);
  ~VideoWriter();  // without finish(): the target is untouched and the temp file removed
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // A display-encoded RGB frame of any size, scaled to the video's (area-averaged when
  // smaller).
  void add_frame(const render::Image& image);
  // Flushes the encoder, writes the container's index and puts the file in place.
  void finish();

  int width() const;
  int height() const;
  int frames() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace impasto::app
