// `impasto recover`, headless: a session that did not end cleanly is rebuilt into the
// painting it held (--apply) or forgotten (--discard), and is then no longer offered.
#include <gtest/gtest.h>
#include <unistd.h>
#include <impasto/input/stroke_file.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "command_line.hpp"
#include "impasto/session/recovery_folder.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/session/session_registry.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

class RecoverCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("impasto_recover_command_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    if (const char* old = std::getenv("XDG_STATE_HOME")) old_state_ = old;
    ::setenv("XDG_STATE_HOME", (dir_ / "state").c_str(), 1);
    folder_ = session::recovery_folder();
  }
  void TearDown() override {
    if (old_state_.empty()) {
      ::unsetenv("XDG_STATE_HOME");
    } else {
      ::setenv("XDG_STATE_HOME", old_state_.c_str(), 1);
    }
    fs::remove_all(dir_);
  }

  // A session that was killed: its recording (a loaded stroke) and its entry, not ended.
  input::StrokeFile crashed_session(const std::string& id) {
    const fs::path strokes = folder_ / (id + ".strokes");
    input::StrokeFile file;
    file.events = {input::CanvasEvent{64, 48, 254.0}, input::OriginEvent{},
                   input::LoadEvent{20.0, {{"Red", 1.0}}, {}}};
    for (int i = 0; i <= 10; ++i) {
      paintcore::PenSample s;
      s.time_s = 0.01 * i;
      s.x_mm = 1.0 + 0.4 * i;
      s.y_mm = 2.5;
      s.pressure = i < 10 ? 0.7f : 0.0f;
      s.buttons = paintcore::kPenInRange | (i < 10 ? paintcore::kPenTip : 0u);
      file.events.push_back(input::SampleEvent{s});
    }
    input::StrokeRecorder recorder(strokes);
    for (const auto& e : file.events) recorder.record(e);
    session::LiveSession live(folder_, id, std::nullopt, strokes);  // gone without end_cleanly()
    return file;
  }

  static void run(const std::string& args) { run_command_in_process(args); }

  fs::path dir_, folder_;
  std::string old_state_;
};

TEST_F(RecoverCommand, ApplyRebuildsThePaintingAndForgetsTheSession) {
  const input::StrokeFile file = crashed_session("one");
  ASSERT_EQ(session::unfinished_sessions(folder_).size(), 1u);
  const fs::path out = dir_ / "recovered.impasto";
  run("recover --apply latest --save " + out.string());
  session::ReplayOptions options;
  options.threads = 1;
  EXPECT_EQ(paintcore::Painting::load(out, 1).state_hash(), replay(file, options).state_hash());
  EXPECT_TRUE(session::unfinished_sessions(folder_).empty());
  EXPECT_THROW(run("recover --apply latest --save " + (dir_ / "again.impasto").string()),
               std::runtime_error);
}

TEST_F(RecoverCommand, ApplyNeverReplacesAFileUnlessForced) {
  crashed_session("two");
  const fs::path out = dir_ / "taken.impasto";
  paintcore::Painting({16, 16, 150.0, 1}, 1).save(out);
  const auto before = fs::file_size(out);
  EXPECT_THROW(run("recover --apply two --save " + out.string()), std::runtime_error);
  EXPECT_EQ(fs::file_size(out), before);
  EXPECT_EQ(session::unfinished_sessions(folder_).size(), 1u);
  run("recover --apply two --force --save " + out.string());
  EXPECT_NE(fs::file_size(out), before);
}

TEST_F(RecoverCommand, DiscardForgetsTheSessionButKeepsItsRecording) {
  crashed_session("three");
  run("recover --discard three");
  EXPECT_TRUE(session::unfinished_sessions(folder_).empty());
  EXPECT_TRUE(fs::exists(folder_ / "three.strokes"));
  EXPECT_THROW(run("recover --discard three"), std::runtime_error);
}

}  // namespace
}  // namespace impasto::app
