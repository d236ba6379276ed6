#include "video_writer.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "impasto/files/atomic_file.hpp"
#include "impasto/util/text.hpp"

namespace impasto::app {

namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct CodecChoice {
  AVCodecID id;
  AVPixelFormat pixels;
  const char* name;
};

CodecChoice codec_for(VideoKind kind) {
  switch (kind) {
    case VideoKind::mp4:
      return {AV_CODEC_ID_H264, AV_PIX_FMT_YUV420P, "H.264"};
    case VideoKind::webm:
      return {AV_CODEC_ID_VP9, AV_PIX_FMT_YUV420P, "VP9"};
    case VideoKind::gif:
      return {AV_CODEC_ID_GIF, AV_PIX_FMT_RGB8, "GIF"};
  }
  throw std::logic_error("video kind");
}

}  // namespace

VideoKind video_kind(const std::filesystem::path& path) {
  const std::string extension = util::ascii_lowercase(path.extension().string());
  if (extension == ".mp4") return VideoKind::mp4;
  if (extension == ".webm") return VideoKind::webm;
  if (extension == ".gif") return VideoKind::gif;
  throw std::runtime_error(path.string() + ": a video is FILE.mp4 (H.264), FILE.webm (VP9) or " +
                           "FILE.gif");
}

struct VideoWriter::State {
  std::filesystem::path path;
  files::AtomicFile file;  // the temp file, put in place at the end
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  std::vector<unsigned char> rgb;  // the frame being converted, 8-bit RGB
  int frames = 0;
  bool finished = false;

  explicit State(const std::filesystem::path& target) : path(target), file(target) {}
  ~State() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format != nullptr) {
      if (format->pb != nullptr) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw std::runtime_error(path.string() + ": " + what +
                             (code < 0 ? " (" + av_error(code) + ")" : std::string()));
  }

  // Sends `f` (null: the end) and writes every packet the encoder has ready.
  void encode(const AVFrame* f) {
    int result = avcodec_send_frame(codec, f);
    if (result < 0) fail("cannot encode frame " + std::to_string(frames), result);
    for (;;) {
      result = avcodec_receive_packet(codec, packet);
      if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return;
      if (result < 0) fail("cannot encode frame " + std::to_string(frames), result);
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      result = av_interleaved_write_frame(format, packet);
      if (result < 0) fail("cannot write the video", result);
    }
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& path, int width, int height, double fps) {
  const CodecChoice choice = codec_for(video_kind(path));
  if (!(fps > 0.0 && fps <= 240.0))
    throw std::runtime_error(path.string() + ": the frame rate must be in (0, 240]");
  width -= width % 2;
  height -= height % 2;
  if (width < 2 || height < 2 || width > 16384 || height > 16384)
    throw std::runtime_error(path.string() + ": a video is 2x2 to 16384x16384 pixels, not " +
                             std::to_string(width) + "x" + std::to_string(height));
  av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not the user's business
  state_ = std::make_unique<State>(path);
  State& s = *state_;
  // The container from the target's name; the bytes to the temp file beside it.
  int result = avformat_alloc_output_context2(&s.format, nullptr, nullptr, path.string().c_str());
  if (result < 0 || s.format == nullptr) s.fail("no container for this file type", result);
  const AVCodec* encoder = avcodec_find_encoder(choice.id);
  if (encoder == nullptr)
    s.fail(std::string("this system's libavcodec has no ") + choice.name + " encoder", 0);
  s.codec = avcodec_alloc_context3(encoder);
  s.packet = av_packet_alloc();
  s.frame = av_frame_alloc();
  if (s.codec == nullptr || s.packet == nullptr || s.frame == nullptr)
    s.fail("out of memory for the encoder", 0);
  const AVRational rate = av_d2q(fps, 100000);
  s.codec->width = width;
  s.codec->height = height;
  s.codec->time_base = av_inv_q(rate);
  s.codec->framerate = rate;
  s.codec->pix_fmt = choice.pixels;
  s.codec->gop_size = std::max(1, static_cast<int>(std::lround(fps)));
  s.codec->thread_count = 0;  // the encoder's own choice: every core
  // What the frames are: sRGB, BT.709 primaries, limited-range BT.709 YUV.
  s.codec->color_primaries = AVCOL_PRI_BT709;
  s.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
  s.codec->colorspace = AVCOL_SPC_BT709;
  s.codec->color_range = AVCOL_RANGE_MPEG;
  if (choice.id == AV_CODEC_ID_H264) {
    av_opt_set(s.codec->priv_data, "crf", "16", 0);  // near transparent for a painting
    av_opt_set(s.codec->priv_data, "preset", "medium", 0);
  } else if (choice.id == AV_CODEC_ID_VP9) {
    s.codec->bit_rate = 0;  // constant quality
    av_opt_set(s.codec->priv_data, "crf", "24", 0);
    av_opt_set(s.codec->priv_data, "deadline", "good", 0);
    av_opt_set(s.codec->priv_data, "cpu-used", "4", 0);
  }
  if (s.format->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  result = avcodec_open2(s.codec, encoder, nullptr);
  if (result < 0) s.fail(std::string("cannot open the ") + choice.name + " encoder", result);
  s.stream = avformat_new_stream(s.format, nullptr);
  if (s.stream == nullptr) s.fail("out of memory for the video stream", 0);
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = rate;
  result = avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (result < 0) s.fail("cannot describe the video stream", result);
  result = avio_open(&s.format->pb, s.file.temp_path().c_str(), AVIO_FLAG_WRITE);
  if (result < 0) s.fail("cannot write " + s.file.temp_path().string(), result);
  result = avformat_write_header(s.format, nullptr);
  if (result < 0) s.fail("cannot write the video's header", result);
  s.frame->format = choice.pixels;
  s.frame->width = width;
  s.frame->height = height;
  result = av_frame_get_buffer(s.frame, 0);
  if (result < 0) s.fail("out of memory for a frame", result);
}

VideoWriter::~VideoWriter() = default;

int VideoWriter::width() const {
  return state_->codec->width;
}
int VideoWriter::height() const {
  return state_->codec->height;
}
int VideoWriter::frames() const {
  return state_->frames;
}

void VideoWriter::add_frame(const render::Image& image) {
  State& s = *state_;
  if (s.finished) throw std::logic_error("VideoWriter::add_frame after finish");
  if (image.width < 1 || image.height < 1) s.fail("an empty frame", 0);
  const std::size_t values = static_cast<std::size_t>(image.width) * image.height * 3;
  s.rgb.resize(values);
  for (std::size_t i = 0; i < values; ++i)
    s.rgb[i] =
        static_cast<unsigned char>(std::lround(std::clamp(image.rgb[i], 0.0f, 1.0f) * 255.0f));
  const bool smaller = image.width > s.codec->width || image.height > s.codec->height;
  s.scaler = sws_getCachedContext(
      s.scaler, image.width, image.height, AV_PIX_FMT_RGB24, s.codec->width, s.codec->height,
      s.codec->pix_fmt, (smaller ? SWS_AREA : SWS_BICUBIC) | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
      nullptr, nullptr, nullptr);
  if (s.scaler == nullptr) s.fail("cannot convert the frames to the video's format", 0);
  // RGB (full range) to BT.709 YUV (limited range), as the stream says.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  int result = av_frame_make_writable(s.frame);
  if (result < 0) s.fail("out of memory for a frame", result);
  const std::uint8_t* source[1] = {s.rgb.data()};
  const int stride[1] = {3 * image.width};
  sws_scale(s.scaler, source, stride, 0, image.height, s.frame->data, s.frame->linesize);
  s.frame->pts = s.frames;
  s.encode(s.frame);
  ++s.frames;
}

void VideoWriter::finish() {
  State& s = *state_;
  if (s.finished) return;
  s.encode(nullptr);
  int result = av_write_trailer(s.format);
  if (result < 0) s.fail("cannot finish the video", result);
  result = avio_closep(&s.format->pb);
  if (result < 0) s.fail("cannot write the video", result);
  s.file.commit();
  s.finished = true;
}

}  // namespace impasto::app
