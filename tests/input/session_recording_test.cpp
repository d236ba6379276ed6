// A session recording never fails silently and never tears: a full disk stops it at a whole
// line with the reason kept; names are never shared and a planted symlink is not followed;
// a torn last line (from any writer) is skipped with a warning and everything before it read.
#include <impasto/input/stroke_file.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "file_size_limit.hpp"

namespace impasto::input {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() / ("impasto_recording_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

StrokeEvent sample(int i) {
  paintcore::PenSample s;
  s.time_s = 0.01 * i;
  s.x_mm = 10.0 + i / 3.0;
  s.y_mm = 20.0 - i / 7.0;
  s.pressure = 0.5f;
  s.buttons = paintcore::kPenInRange | paintcore::kPenTip;
  return SampleEvent{s};
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// For limits that fall on the header's end, inside a line and a few lines on, the
// recording stops at a whole line: the file ends in a newline, reads with no warning, and
// holds exactly the events the recorder said it took.
TEST(SessionRecording, FullDiskStopsTheRecordingAtAWholeLineAndSaysWhy) {
  TempDir dir;
  for (std::uint64_t extra : {0u, 1u, 17u, 40u, 41u, 300u, 2000u}) {
    const fs::path path = dir / ("full_" + std::to_string(extra) + ".strokes");
    StrokeRecorder recorder(path);
    ASSERT_TRUE(recorder.record(OriginEvent{}));
    std::size_t accepted = 0;
    {
      testing_support::FileSizeLimit full(fs::file_size(path) + extra);
      for (int i = 0; i < 200; ++i) {
        if (!recorder.record(sample(i))) break;
        ++accepted;
      }
    }
    ASSERT_TRUE(recorder.failed()) << "a limit of +" << extra << " bytes never failed";
    EXPECT_LT(accepted, 200u);
    EXPECT_NE(recorder.error().find(path.string()), std::string::npos) << recorder.error();
    EXPECT_NE(recorder.error().find("write failed"), std::string::npos) << recorder.error();
    // Nothing more is written once it failed, even with room again.
    EXPECT_FALSE(recorder.record(sample(999)));
    EXPECT_FALSE(recorder.sync());
    const std::string text = contents(path);
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n') << "torn line left at +" << extra << " bytes";
    const StrokeFile read = read_stroke_file(path);
    EXPECT_TRUE(read.warnings.empty());
    ASSERT_EQ(read.events.size(), accepted + 1);
    for (std::size_t i = 0; i < accepted; ++i) EXPECT_EQ(read.events[i + 1], sample(int(i)));
  }
}

TEST(SessionRecording, SyncMakesEveryRecordDurable) {
  TempDir dir;
  StrokeRecorder recorder(dir / "sync.strokes");
  EXPECT_TRUE(recorder.needs_sync());  // the header
  EXPECT_TRUE(recorder.sync());
  EXPECT_FALSE(recorder.needs_sync());
  EXPECT_TRUE(recorder.record(sample(1)));
  EXPECT_TRUE(recorder.needs_sync());
  EXPECT_TRUE(recorder.sync());
  EXPECT_FALSE(recorder.needs_sync());
}

TEST(SessionRecording, AnExistingFileIsNeverOverwritten) {
  TempDir dir;
  const fs::path path = dir / "taken.strokes";
  StrokeRecorder first(path);
  ASSERT_TRUE(first.record(sample(1)));
  EXPECT_THROW(StrokeRecorder second(path), std::runtime_error);
  EXPECT_EQ(read_stroke_file(path).events.size(), 1u);
}

TEST(SessionRecording, APlantedSymlinkIsNotFollowed) {
  TempDir dir;
  const fs::path target = dir / "precious.txt";
  std::ofstream(target) << "keep me\n";
  const fs::path link = dir / "session.strokes";
  fs::create_symlink(target, link);
  try {
    StrokeRecorder recorder(link);
    FAIL() << "recorded through a symlink";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(link.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(contents(target), "keep me\n");
  // A dangling link would have created its target.
  const fs::path dangling = dir / "dangling.strokes";
  fs::create_symlink(dir / "created_through_link", dangling);
  EXPECT_THROW(StrokeRecorder recorder(dangling), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "created_through_link"));
}

StrokeFile parse(const std::string& text) {
  std::istringstream in(text);
  return parse_strokes(in, "s.strokes");
}

TEST(SessionRecording, ATornLastLineIsSkippedWithAWarning) {
  const std::string good = "from new\ncanvas 64 64 150\npen 0 1 2 0.5 0 0 0 17\n";
  // Version 2 ends every record with a newline: a last line without one is torn, even when
  // what is left of it would parse (here the buttons lost a digit).
  const StrokeFile v2 = parse("impasto-strokes 2\n" + good + "pen 0.01 1 2 0.5 0 0 0 1");
  EXPECT_EQ(v2.events.size(), 3u);
  ASSERT_EQ(v2.warnings.size(), 1u);
  EXPECT_NE(v2.warnings[0].find("s.strokes:5:"), std::string::npos) << v2.warnings[0];
  // Version 1: skipped only when it does not parse; a whole last record is kept.
  const StrokeFile v1_torn = parse("impasto-strokes 1\n" + good + "pen 0.01 1 2 0.");
  EXPECT_EQ(v1_torn.events.size(), 3u);
  EXPECT_EQ(v1_torn.warnings.size(), 1u);
  const StrokeFile v1_whole = parse("impasto-strokes 1\n" + good + "pen 0.01 1 2 0.5 0 0 0 17");
  EXPECT_EQ(v1_whole.events.size(), 4u);
  EXPECT_TRUE(v1_whole.warnings.empty());
  // A bad line that is not the last is still an error naming the file and line.
  EXPECT_THROW(parse("impasto-strokes 2\npen 0.01 1 2 0.\n" + good), InputFormatError);
  // Events know their lines, for replay errors.
  EXPECT_EQ(v2.where(2), "s.strokes:4");
}

TEST(SessionRecording, OriginAndSaveMarksRoundTripAnyPath) {
  StrokeFile file;
  const std::string odd = "/home/a b/\"quoted\" 100%\n/caf\xc3\xa9.impasto";
  file.events = {OriginEvent{false, odd, 0x0123456789abcdefull}, CanvasEvent{64, 32, 150.0},
                 sample(0), SavedEvent{odd, 0xfedcba9876543210ull}, sample(1)};
  std::stringstream text;
  format_strokes(text, file);
  EXPECT_EQ(text.str().find('\n', text.str().find("from")),
            text.str().find("\ncanvas"));  // the path's newline is escaped, one line a record
  EXPECT_EQ(parse_strokes(text, "m"), file);
  EXPECT_EQ(parse("impasto-strokes 2\nfrom new\n").events.at(0), StrokeEvent{OriginEvent{}});
  EXPECT_THROW(parse("impasto-strokes 2\nfrom new\nfrom new\n"), InputFormatError);
  EXPECT_THROW(parse("impasto-strokes 2\nsaved \"/x\" 12\n"), InputFormatError);
  EXPECT_THROW(parse("impasto-strokes 2\nsaved \"/x%4\" 0123456789abcdef\n"), InputFormatError);
}

}  // namespace
}  // namespace impasto::input
