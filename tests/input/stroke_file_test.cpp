// Round trips of the native stroke format and the recorder.
#include <impasto/input/stroke_file.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace impasto::input {
namespace {

using paintcore::PenSample;

SampleEvent pen(double t, double x, double y, float p, std::uint32_t buttons) {
  PenSample s;
  s.time_s = t;
  s.x_mm = x;
  s.y_mm = y;
  s.pressure = p;
  s.tilt_x_deg = -12.5f;
  s.tilt_y_deg = 33.25f;
  s.rotation_deg = 359.5f;
  s.buttons = buttons;
  return SampleEvent{s};
}

StrokeFile session() {
  StrokeFile file;
  file.events = {
      CanvasEvent{2048, 1536, 300.0},
      ToolEvent{"brush"},
      BrushEvent{"round", 4.5, 0.7, {{"bristles", 200.0}, {"splay", 0.125}}},
      LoadEvent{30.0, {{"White", 2.0}, {"Blue Red Shade (Green Shade)", 1.0}}, {}},
      LoadEvent{5.0, {{"White", 1.0}}, "fluid"},
      LoadEvent{5.0, {{"White", 1.0}}, "soft", "matte:0.5"},
      LoadEvent{5.0, {{"White", 1.0}}, {}, "gloss"},
      pen(0.0, 10.0, 20.0, 0.0f, paintcore::kPenInRange),
      // Values with no short decimal form: the writer must keep every bit.
      pen(0.1, 1.0 / 3.0, std::nextafter(20.0, 30.0), 1.0f / 3.0f,
          paintcore::kPenInRange | paintcore::kPenTip),
      pen(0.2, 1e-300, 123456789.123456789, 1.0f, paintcore::kPenTip | paintcore::kPenBarrel1),
      WipeEvent{},
      DryEvent{0.25},
      VarnishEvent{paintcore::Finish::matte, 0.05, std::nullopt},
      VarnishEvent{paintcore::Finish::gloss, 1.0 / 30.0, paintcore::CellRect{3, 4, 13, 24}},
      UndoEvent{},
      RedoEvent{},
      ToolEvent{"eraser"},
  };
  return file;
}

TEST(StrokeFile, WriteThenReadGivesIdenticalEvents) {
  const StrokeFile original = session();
  std::stringstream text;
  format_strokes(text, original);
  const StrokeFile read = parse_strokes(text, "memory");
  EXPECT_EQ(read.version, kStrokeFormatVersion);
  ASSERT_EQ(read.events.size(), original.events.size());
  for (std::size_t i = 0; i < read.events.size(); ++i) {
    EXPECT_EQ(read.events[i], original.events[i]) << "event " << i;
  }
}

TEST(StrokeFile, FirstLineIsTheVersionHeader) {
  std::stringstream text;
  format_strokes(text, session());
  std::string first;
  std::getline(text, first);
  EXPECT_EQ(first, "impasto-strokes 2");
}

TEST(StrokeFile, ReadsCommentsBlankLinesAndQuotedNames) {
  std::istringstream text(
      "impasto-strokes 1\n"
      "# a session\n"
      "\n"
      "   load 12.5 \"Cadmium Red # 2\" 3 \"White\" 1   # trailing comment\n"
      "pen 0.5 1 2 0.5 0 0 0 17\n");
  const StrokeFile file = parse_strokes(text, "memory");
  ASSERT_EQ(file.events.size(), 2u);
  const auto& load = std::get<LoadEvent>(file.events[0]);
  EXPECT_EQ(load.volume_mm3, 12.5);
  ASSERT_EQ(load.mix.size(), 2u);
  EXPECT_EQ(load.mix[0].pigment, "Cadmium Red # 2");
  EXPECT_EQ(load.mix[0].parts, 3.0);
  EXPECT_EQ(load.mix[1].pigment, "White");
  const auto& s = std::get<SampleEvent>(file.events[1]).sample;
  EXPECT_EQ(s.buttons, paintcore::kPenTip | paintcore::kPenInRange);
  EXPECT_FLOAT_EQ(s.pressure, 0.5f);
}

TEST(StrokeFile, BrushKeysInAnyOrder) {
  std::istringstream text("impasto-strokes 1\nbrush flat stiffness=1 width=3 size=2\n");
  const auto brush = std::get<BrushEvent>(parse_strokes(text, "memory").events.at(0));
  EXPECT_EQ(brush.head, "flat");
  EXPECT_EQ(brush.size_mm, 2.0);
  EXPECT_EQ(brush.stiffness, 1.0);
  ASSERT_EQ(brush.params.size(), 1u);
  EXPECT_EQ(brush.params[0], (BrushParam{"width", 3.0}));
}

// A head's bristle settings are checked against the engine's one table of their ranges
// (paintcore::kBristleSettings) when the file is read, naming the line and the key.
TEST(StrokeFile, BristleSettingsOutsideTheirRangesNameTheLineAndKey) {
  for (const char* setting :
       {"bristle_depth=-1", "bristle_spacing=1e308", "splay=2", "bristle_jitter=1.5"}) {
    std::istringstream text(std::string("impasto-strokes 2\nbrush round size=4 stiffness=0.5 ") +
                            setting + "\n");
    try {
      parse_strokes(text, "b.strokes");
      ADD_FAILURE() << setting << " was taken";
    } catch (const InputFormatError& e) {
      const std::string key = std::string(setting).substr(0, std::string(setting).find('='));
      EXPECT_NE(std::string(e.what()).find("b.strokes:2"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("must be in"), std::string::npos) << e.what();
    }
  }
  std::istringstream ok("impasto-strokes 2\nbrush round size=4 stiffness=0.5 bristle_depth=0.1\n");
  const StrokeFile file = parse_strokes(ok, "b.strokes");
  EXPECT_TRUE(file.warnings.empty());
}

TEST(StrokeFile, WriterRefusesWhatTheReaderWouldReject) {
  StrokeFile bad;
  bad.events = {LoadEvent{1.0, {{"Quote \" inside", 1.0}}, {}}};
  std::ostringstream out;
  EXPECT_THROW(format_strokes(out, bad), std::runtime_error);
  bad.events = {pen(0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.5f, 0)};
  EXPECT_THROW(format_strokes(out, bad), std::runtime_error);
  bad.events = {ToolEvent{"two words"}};
  EXPECT_THROW(format_strokes(out, bad), std::runtime_error);
}

TEST(StrokeFile, VarnishRecordsReadAsWritten) {
  std::istringstream text(
      "impasto-strokes 2\n"
      "varnish satin 0.03\n"
      "varnish gloss 0.1 10 20 30 40  # x y width height\n");
  const StrokeFile read = parse_strokes(text, "memory");
  ASSERT_EQ(read.events.size(), 2u);
  EXPECT_EQ(read.events[0], StrokeEvent(VarnishEvent{paintcore::Finish::satin, 0.03, {}}));
  EXPECT_EQ(read.events[1], StrokeEvent(VarnishEvent{paintcore::Finish::gloss, 0.1,
                                                     paintcore::CellRect{10, 20, 40, 60}}));
  std::ostringstream out;
  format_strokes(out, read);
  EXPECT_NE(out.str().find("\nvarnish gloss 0.1 10 20 30 40\n"), std::string::npos) << out.str();
  // A region the reader would refuse is not written.
  StrokeFile bad;
  bad.events = {VarnishEvent{paintcore::Finish::gloss, 0.1, paintcore::CellRect{5, 5, 5, 9}}};
  EXPECT_THROW(format_strokes(out, bad), std::runtime_error);
  bad.events = {VarnishEvent{paintcore::Finish::gloss, 0.0, std::nullopt}};
  EXPECT_THROW(format_strokes(out, bad), std::runtime_error);
}

TEST(StrokeFile, QualityRecordsReadAsWritten) {
  std::istringstream text(
      "impasto-strokes 2\n"
      "quality fast\n"
      "quality exact  # a comment\n");
  const StrokeFile read = parse_strokes(text, "memory");
  ASSERT_EQ(read.events.size(), 2u);
  EXPECT_EQ(read.events[0], StrokeEvent(QualityEvent{paintcore::StepQuality::fast}));
  EXPECT_EQ(read.events[1], StrokeEvent(QualityEvent{paintcore::StepQuality::exact}));
  std::ostringstream out;
  format_strokes(out, read);
  EXPECT_NE(out.str().find("\nquality fast\nquality exact\n"), std::string::npos) << out.str();
}

TEST(StrokeFile, SplitsStrokesByTheTipBit) {
  std::vector<PenSample> samples(7);
  const std::uint32_t tip = paintcore::kPenTip;
  const std::uint32_t bits[] = {0, tip, tip, 0, tip, 0, tip};
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i].buttons = bits[i];
  const auto strokes = split_strokes(samples);
  ASSERT_EQ(strokes.size(), 3u);
  EXPECT_EQ(strokes[0], (StrokeSpan{1, 3}));
  EXPECT_EQ(strokes[1], (StrokeSpan{4, 5}));
  EXPECT_EQ(strokes[2], (StrokeSpan{6, 7}));
  EXPECT_TRUE(split_strokes({}).empty());
}

class TempPath {
 public:
  explicit TempPath(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {}
  ~TempPath() { std::filesystem::remove(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

TEST(StrokeFile, FileRoundTrip) {
  TempPath tmp("impasto_roundtrip.strokes");
  write_stroke_file(tmp.path(), session());
  EXPECT_EQ(read_stroke_file(tmp.path()), session());
}

TEST(StrokeRecorder, EveryRecordIsOnDiskAtOnce) {
  TempPath tmp("impasto_recorder.strokes");
  const StrokeFile expected = session();
  StrokeRecorder recorder(tmp.path());
  StrokeFile so_far;
  for (const StrokeEvent& event : expected.events) {
    EXPECT_TRUE(recorder.record(event));
    so_far.events.push_back(event);
    // Read while the recorder is still open: nothing may be waiting in a buffer.
    EXPECT_EQ(read_stroke_file(tmp.path()), so_far);
  }
  EXPECT_EQ(recorder.events_recorded(), expected.events.size());
}

}  // namespace
}  // namespace impasto::input
