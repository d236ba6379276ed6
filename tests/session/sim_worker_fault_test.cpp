// The painting window's simulation thread under a full disk (a file size limit): a recording
// that cannot be written stops with the reason kept (the window's banner) and the painting
// goes on exactly as unrecorded; an autosave that cannot be written keeps the last good one.
#include <gtest/gtest.h>
#include <unistd.h>
#include <impasto/input/stroke_file.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "../input/file_size_limit.hpp"
#include "impasto/session/sim_worker.hpp"

namespace impasto::session {
namespace {

namespace fs = std::filesystem;
using testing_support::FileSizeLimit;

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("impasto_worker_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

paintcore::Painting small_painting() {
  return paintcore::Painting(paintcore::CanvasSpec{80, 60, 254.0, 1}, 1);
}

// `count` strokes, the first starting at `first` seconds (a recording's time never goes back).
std::vector<input::StrokeEvent> strokes(int count, int first = 0) {
  std::vector<input::StrokeEvent> events;
  for (int k = first; k < first + count; ++k) {
    events.push_back(input::LoadEvent{20.0, {{"Blue Red Shade", 1.0}}, {}});
    for (int i = 0; i <= 8; ++i) {
      paintcore::PenSample s;
      s.time_s = k + 0.01 * i;
      s.x_mm = 2.0 + 0.8 * i;
      s.y_mm = 2.0 + k;
      s.pressure = i < 8 ? 0.8f : 0.0f;
      s.buttons = paintcore::kPenInRange | (i < 8 ? paintcore::kPenTip : 0u);
      events.push_back(input::SampleEvent{s});
    }
  }
  return events;
}

SessionRecording recording_at(const fs::path& path) {
  SessionRecording recording;
  recording.recorder = std::make_unique<input::StrokeRecorder>(path);
  return recording;
}

std::uint64_t hash_of(SimWorker& worker) {
  worker.wait_idle();
  return worker.with_painting([](const paintcore::Painting& p) { return p.state_hash(); });
}

TEST(SimWorkerFaults, AFullDiskStopsTheRecordingNotThePaintingAndSaysSo) {
  TempDir dir;
  const auto events = strokes(4);
  SimWorker unrecorded(small_painting(), SessionRecording{});
  for (const auto& e : events) unrecorded.submit(e);
  const fs::path path = dir / "session.strokes";
  SimWorker worker(small_painting(), recording_at(path));
  worker.wait_idle();
  {
    FileSizeLimit full(fs::file_size(path) + 700);  // room for a stroke and a bit
    for (const auto& e : events) worker.submit(e);
    worker.wait_idle();
  }
  const SimStats stats = worker.stats();
  EXPECT_NE(stats.recording_error.find(path.string()), std::string::npos) << stats.recording_error;
  EXPECT_TRUE(stats.last_error.empty()) << stats.last_error;
  EXPECT_EQ(hash_of(worker), hash_of(unrecorded)) << "an event was dropped with the recording";
  // What was recorded is whole lines: it reads without warnings, a prefix of the session.
  const input::StrokeFile read = input::read_stroke_file(path);
  EXPECT_TRUE(read.warnings.empty());
  EXPECT_GT(read.events.size(), 3u);
  EXPECT_LT(read.events.size(), events.size());
  EXPECT_FALSE(worker.recording_path()) << "recording goes on after a failed write";
}

TEST(SimWorkerFaults, AFailedAutosaveKeepsTheLastGoodOneAndSaysSo) {
  TempDir dir;
  const fs::path autosave = dir / "x.autosave.impasto";
  const fs::path path = dir / "session.strokes";
  SimWorker worker(small_painting(), recording_at(path));
  for (const auto& e : strokes(1)) worker.submit(e);
  worker.autosave(autosave);
  const std::uint64_t first = hash_of(worker);
  ASSERT_EQ(worker.stats().autosaves, 1u) << worker.stats().autosave_error;
  for (const auto& e : strokes(2, 1)) worker.submit(e);
  worker.wait_idle();
  {
    FileSizeLimit full(1000);  // far less than a painting
    worker.autosave(autosave);
    worker.wait_idle();
  }
  SimStats stats = worker.stats();
  EXPECT_EQ(stats.autosaves, 1u);
  EXPECT_NE(stats.autosave_error.find("autosave failed"), std::string::npos)
      << stats.autosave_error;
  EXPECT_EQ(paintcore::Painting::load(autosave).state_hash(), first);
  // With room again, the next autosave succeeds and the banner goes.
  worker.autosave(autosave);
  const std::uint64_t now = hash_of(worker);
  stats = worker.stats();
  EXPECT_EQ(stats.autosaves, 2u);
  EXPECT_TRUE(stats.autosave_error.empty()) << stats.autosave_error;
  EXPECT_EQ(paintcore::Painting::load(autosave).state_hash(), now);
  EXPECT_TRUE(stats.recording_error.empty()) << stats.recording_error;
  // Both good autosaves are marked in the recording, the failed one is not.
  int marks = 0;
  for (const auto& e : input::read_stroke_file(path).events)
    marks += std::holds_alternative<input::SavedEvent>(e);
  EXPECT_EQ(marks, 2);
}

}  // namespace
}  // namespace impasto::session
