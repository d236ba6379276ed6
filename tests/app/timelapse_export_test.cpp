// File > Export time-lapse... without a window: the dialog's choice becomes the request
// `impasto timelapse` would make, read from the recording as it was when asked; the job
// writes the video on its own thread, and stopping it leaves no file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "../common/scratch_folder.hpp"
#include "../common/short_session.hpp"
#include "impasto/input/stroke_file.hpp"
#include "window/timelapse_export.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

class TimelapseExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_timelapse_export_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    sources_ = {{"this session", impasto::test::write_short_session(dir_ / "session.strokes")}};
    choice_.stem = (dir_ / "growth").string();
    choice_.format = VideoFormat::kWebm;
    choice_.width = 120;
    choice_.height = 80;
    choice_.seconds = 1.0;
    choice_.fps = 5.0;
    choice_.hold_seconds = 0.0;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Waits for the job however busy the machine is (no clock decides the test).
  static void wait_for(const TimelapseJob& job) {
    while (!job.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }

  fs::path dir_;
  std::vector<TimelapseSource> sources_;
  TimelapseChoice choice_;
};

TEST_F(TimelapseExportTest, TheChoiceIsTheCommandLinesRequestReadAsItWasAsked) {
  choice_.turn_light = true;
  choice_.turn_to_deg = 90.0;
  render::RenderSettings settings;
  settings.light_azimuth_deg = 10.0;
  settings.light = "A";
  const TimelapseRequest request = timelapse_request(choice_, sources_, settings);
  EXPECT_EQ(request.out, dir_ / "growth.webm");
  EXPECT_EQ(request.options.fps, 5.0);
  EXPECT_EQ(request.options.growth_seconds, 1.0);
  EXPECT_EQ(request.options.hold_seconds, 0.0);
  EXPECT_EQ(request.options.light_azimuth_end_deg, 90.0);
  EXPECT_EQ(request.options.settings.light, "A");
  EXPECT_EQ(request.options.settings.light_azimuth_deg, 10.0);
  EXPECT_EQ(request.options.settings.threads, 1) << "the window's simulation keeps a core";
  ASSERT_TRUE(request.frame_size.has_value());
  EXPECT_EQ(request.frame_size->width, 120);
  EXPECT_EQ(request.strokes, input::read_stroke_file(sources_[0].recording));
  EXPECT_EQ(request.strokes.source, sources_[0].recording.string())
      << "the kept origin is found beside the recording";
  // The window goes on recording: the request keeps what it read.
  const std::size_t events = request.strokes.events.size();
  std::ofstream(sources_[0].recording, std::ios::app) << "wipe\n";
  EXPECT_EQ(request.strokes.events.size(), events);

  choice_.format = VideoFormat::kGif;
  EXPECT_EQ(timelapse_file(choice_), dir_ / "growth.gif");
  choice_.source = 1;
  EXPECT_THROW(timelapse_request(choice_, sources_, settings), std::runtime_error);
}

TEST_F(TimelapseExportTest, TheJobWritesTheVideoOnItsOwnThread) {
  TimelapseJob job(timelapse_request(choice_, sources_, render::RenderSettings{}));
  wait_for(job);
  ASSERT_TRUE(job.succeeded()) << job.outcome();
  EXPECT_NE(job.outcome().find("120x80, 5 frames"), std::string::npos) << job.outcome();
  EXPECT_GT(fs::file_size(dir_ / "growth.webm"), 0u);
  EXPECT_EQ(job.fraction_done(), 1.0);
}

TEST_F(TimelapseExportTest, StoppedItLeavesNoFile) {
  choice_.seconds = 60.0;  // 300 frames: far from done when stopped
  {
    TimelapseJob job(timelapse_request(choice_, sources_, render::RenderSettings{}));
    job.stop();
    wait_for(job);
    EXPECT_FALSE(job.succeeded());
    EXPECT_NE(job.outcome().find("stopped"), std::string::npos) << job.outcome();
  }
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename(), "session.strokes") << "left behind: " << entry.path();
}

}  // namespace
}  // namespace impasto::app::window
