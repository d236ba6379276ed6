// `impasto timelapse`: a session's growth as a video that libavformat reads back with the asked
// frame count and size, whose last frame is the replayed painting's render (to the codec's
// rounding), whose light can turn, and which is never left half written.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/scratch_folder.hpp"
#include "../common/short_session.hpp"
#include "command_line.hpp"
#include "impasto/input/stroke_import.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/session/timelapse.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

// A video decoded: its size, every frame as 8-bit RGB (BT.709, limited range, as written) and,
// for a YUV video, the last frame's luma plane as stored.
struct DecodedVideo {
  int width = 0, height = 0;
  std::vector<std::vector<unsigned char>> frames;
  std::vector<unsigned char> last_luma;
};

DecodedVideo decode(const fs::path& file) {
  DecodedVideo video;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0)
    throw std::runtime_error("cannot open " + file.string());
  avformat_find_stream_info(format, nullptr);
  const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (stream < 0) throw std::runtime_error("no video stream");
  const AVCodec* decoder = avcodec_find_decoder(format->streams[stream]->codecpar->codec_id);
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(codec, format->streams[stream]->codecpar);
  avcodec_open2(codec, decoder, nullptr);
  video.width = codec->width;
  video.height = codec->height;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* scaler = nullptr;
  const auto take_frames = [&] {
    while (avcodec_receive_frame(codec, frame) == 0) {
      if (frame->format == AV_PIX_FMT_YUV420P) {
        video.last_luma.clear();
        for (int y = 0; y < frame->height; ++y)
          video.last_luma.insert(video.last_luma.end(), frame->data[0] + y * frame->linesize[0],
                                 frame->data[0] + y * frame->linesize[0] + frame->width);
      }
      scaler = sws_getCachedContext(
          scaler, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
          frame->width, frame->height, AV_PIX_FMT_RGB24,
          SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(scaler, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      std::vector<unsigned char> rgb(static_cast<std::size_t>(3) * frame->width * frame->height);
      unsigned char* planes[1] = {rgb.data()};
      const int strides[1] = {3 * frame->width};
      sws_scale(scaler, frame->data, frame->linesize, 0, frame->height, planes, strides);
      video.frames.push_back(std::move(rgb));
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == stream && avcodec_send_packet(codec, packet) == 0) take_frames();
    av_packet_unref(packet);
  }
  avcodec_send_packet(codec, nullptr);
  take_frames();
  sws_freeContext(scaler);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  avformat_close_input(&format);
  return video;
}

class Timelapse : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_timelapse_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    session_ = impasto::test::write_short_session(dir_ / "session.strokes");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_, session_;
};

TEST_F(Timelapse, AnMp4HasTheFramesAskedAndEndsOnTheReplayedPaintingsRender) {
  const fs::path out = dir_ / "growth.mp4";
  run_command_in_process("timelapse " + session_.string() + " -o " + out.string() +
                         " --fps 10 --seconds 1.5 --hold 0.5");
  const DecodedVideo video = decode(out);
  EXPECT_EQ(video.width, test::ShortSession::kWidthCells);
  EXPECT_EQ(video.height, test::ShortSession::kHeightCells);
  ASSERT_EQ(video.frames.size(), 15u + 5u);
  // The last frame against `render` of the replayed painting: its luma, as H.264 stores it,
  // within a level or so of the render's (BT.709 limited range) at the default quality. (Its
  // colour is stored at half the resolution, 4:2:0, as players expect: in RGB the textured,
  // saturated strokes are a few levels off on average and up to some 20 at their edges.)
  const paintcore::Painting painting = session::replay(input::load_strokes_any(session_), {});
  const render::Image reference = render::render_painting(painting, render::RenderSettings{});
  ASSERT_EQ(video.last_luma.size(), reference.rgb.size() / 3);
  double sum = 0.0, worst = 0.0;
  for (std::size_t p = 0; p < video.last_luma.size(); ++p) {
    double luma = 0.0;
    for (int c = 0; c < 3; ++c)
      luma += std::array{0.2126, 0.7152, 0.0722}[c] *
              std::lround(std::clamp(reference.rgb[3 * p + c], 0.0f, 1.0f) * 255.0f);
    const double error = std::abs(video.last_luma[p] - (16.0 + 219.0 * luma / 255.0));
    sum += error;
    worst = std::max(worst, error);
  }
  EXPECT_LT(sum / static_cast<double>(video.last_luma.size()), 1.0) << "mean luma error, levels";
  EXPECT_LT(worst, 12.0) << "largest luma error, levels";
  const std::vector<unsigned char>& last = video.frames.back();
  // The growth: the first frame holds less paint than the last (the canvas is lighter).
  const auto mean_of = [](const std::vector<unsigned char>& rgb) {
    double total = 0.0;
    for (unsigned char v : rgb) total += v;
    return total / static_cast<double>(rgb.size());
  };
  EXPECT_GT(mean_of(video.frames.front()), mean_of(last) + 1.0);
}

TEST_F(Timelapse, WebmAndGifAtAnotherSizeAndATurningLight) {
  const fs::path webm = dir_ / "small.webm", gif = dir_ / "small.gif";
  run_command_in_process("timelapse " + session_.string() + " -o " + webm.string() +
                         " --fps 5 --seconds 1 --hold 0 --frame-size 121x81");
  const DecodedVideo v = decode(webm);
  EXPECT_EQ(v.width, 120);  // rounded down to even
  EXPECT_EQ(v.height, 80);
  EXPECT_EQ(v.frames.size(), 5u);
  run_command_in_process("timelapse " + session_.string() + " -o " + gif.string() +
                         " --fps 5 --seconds 0.4 --hold 0.4 --light-turn-to 45");
  const DecodedVideo g = decode(gif);
  ASSERT_EQ(g.frames.size(), 4u);
  // The held frames show the finished painting under a light that keeps turning.
  EXPECT_NE(g.frames[2], g.frames[3]);
}

TEST_F(Timelapse, TheFramesFollowTheSessionAndTheLightTurnsEvenly) {
  const input::StrokeFile file = input::load_strokes_any(session_);
  session::TimelapseOptions options;
  options.fps = 4;
  options.growth_seconds = 1.5;  // 6 frames
  options.hold_seconds = 0.5;    // 2 frames
  options.settings.light_azimuth_deg = 0;
  options.light_azimuth_end_deg = 70;
  EXPECT_EQ(timelapse_growth_frames(file, options), 6);
  std::vector<render::Image> frames;
  const session::TimelapseReport report =
      play_timelapse(file, {}, options, [&](const render::Image& f) { frames.push_back(f); });
  EXPECT_EQ(report.growth_frames, 6);
  EXPECT_EQ(report.hold_frames, 2);
  EXPECT_EQ(report.replay.strokes, 3u);
  ASSERT_EQ(frames.size(), 8u);
  // The last growth frame is the finished painting under the light of that moment.
  const paintcore::Painting painting = session::replay(file, {});
  render::RenderSettings at_frame_six;
  at_frame_six.light_azimuth_deg = 50;  // 0 + 70 · 5 / 7
  EXPECT_EQ(frames[5].rgb, render::render_painting(painting, at_frame_six).rgb);
  // Under a still light each frame re-shades only the tiles the strokes changed since the
  // last: the last frame is still exactly the finished painting's render.
  options.light_azimuth_end_deg.reset();
  frames.clear();
  play_timelapse(file, {}, options, [&](const render::Image& f) { frames.push_back(f); });
  render::RenderSettings still;
  still.light_azimuth_deg = 0;
  EXPECT_EQ(frames.back().rgb, render::render_painting(painting, still).rgb);
  // Real time: the session's 1.22 s at 10 frames a second.
  options.real_time = true;
  options.fps = 10;
  EXPECT_EQ(timelapse_growth_frames(file, options), 13);
}

TEST_F(Timelapse, AVideoLargerThanTheCanvasShadesTheReliefAtItsSize) {
  const paintcore::CanvasSpec canvas{240, 160, 254.0, 1};
  EXPECT_EQ(session::timelapse_shade_scale(canvas, 240, 160), 1);
  EXPECT_EQ(session::timelapse_shade_scale(canvas, 120, 80), 1);
  EXPECT_EQ(session::timelapse_shade_scale(canvas, 242, 160), 2);
  EXPECT_EQ(session::timelapse_shade_scale(canvas, 481, 160), 3);
  EXPECT_EQ(session::timelapse_shade_scale(canvas, 7680, 4320), 4);

  const input::StrokeFile file = input::load_strokes_any(session_);
  session::TimelapseOptions options;
  options.fps = 2;
  options.growth_seconds = 1;
  options.hold_seconds = 0.5;
  options.shade_scale = 2;
  std::vector<render::Image> frames;
  play_timelapse(file, {}, options, [&](const render::Image& f) { frames.push_back(f); });
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames.back().width, 480);
  EXPECT_EQ(frames.back().height, 320);
  // The refined relief's render, not the canvas's cells enlarged.
  const paintcore::Painting painting = session::replay(file, {});
  EXPECT_EQ(frames.back().rgb, render::render_painting(painting.refined(2), {}).rgb);

  // Through the command line: a 2x frame comes out of the encoder at that size.
  const fs::path out = dir_ / "large.webm";
  run_command_in_process("timelapse " + session_.string() + " -o " + out.string() +
                         " --fps 2 --seconds 1 --hold 0 --frame-size 480x320");
  const DecodedVideo video = decode(out);
  EXPECT_EQ(video.width, 480);
  EXPECT_EQ(video.frames.size(), 2u);
}

TEST_F(Timelapse, UnderTheSurfaceModelAsked) {
  const fs::path blinn = dir_ / "blinn.webm", ghs = dir_ / "ghs.webm";
  const std::string common = " --fps 2 --seconds 1 --hold 0";
  run_command_in_process("timelapse " + session_.string() + " -o " + blinn.string() + common);
  run_command_in_process("timelapse " + session_.string() + " -o " + ghs.string() + common +
                         " --surface ghs --medium gloss");
  const DecodedVideo a = decode(blinn), b = decode(ghs);
  ASSERT_EQ(a.frames.size(), 2u);
  ASSERT_EQ(b.frames.size(), 2u);
  EXPECT_NE(a.frames.back(), b.frames.back()) << "the gloss surface shades the paint otherwise";
  EXPECT_THROW(run_command_in_process("timelapse " + session_.string() + " -o " +
                                      (dir_ / "x.webm").string() + " --surface chrome"),
               UsageError);
}

TEST_F(Timelapse, ABadSessionNamesItsLineAndLeavesNoFile) {
  std::ofstream(dir_ / "bad.strokes") << "impasto-strokes 1\ncanvas 64 64 100\n"
                                         "pen 0 1 1 0.5 0 0 0 17\ntool trowel\n";
  const fs::path out = dir_ / "bad.mp4";
  std::string error;
  try {
    run_command_in_process("timelapse " + (dir_ / "bad.strokes").string() + " -o " + out.string() +
                           " --seconds 1");
  } catch (const std::exception& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("bad.strokes:4: "), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".bad.mp4"), std::string::npos)
        << entry.path() << " (a temp file left)";
}

}  // namespace
}  // namespace impasto::app
