// Every way a stroke file can be wrong gets a message naming the file, line and field.
#include <impasto/input/stroke_file.hpp>

#include <gtest/gtest.h>

#include <sstream>

namespace impasto::input {
namespace {

// The message of the error that parsing `text` (as "bad.strokes") throws.
std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_strokes(in, "bad.strokes");
  } catch (const InputFormatError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kHeader = "impasto-strokes 1\n";

struct ErrorCase {
  const char* name;
  std::string text;
  std::string message;  // expected message, exactly
};

// Shown by GoogleTest when a case fails.
void PrintTo(const ErrorCase& c, std::ostream* out) {
  *out << c.name;
}

class StrokeErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(StrokeErrors, MessageNamesFileLineAndField) {
  EXPECT_EQ(error_of(GetParam().text), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    AllCases, StrokeErrors,
    ::testing::Values(
        ErrorCase{"Empty", "", "bad.strokes:1: empty file"},
        ErrorCase{"NoHeader", "pen 0 0 0 0 0 0 0 0\n",
                  "bad.strokes:1: not an Impasto stroke file (the first line must be "
                  "'impasto-strokes 2')"},
        ErrorCase{"UnknownVersion", "impasto-strokes 3\n",
                  "bad.strokes:1: field 'version': unsupported version 3 (this program reads "
                  "versions 1 to 2)"},
        ErrorCase{"VersionNotANumber", "impasto-strokes one\n",
                  "bad.strokes:1: field 'version': expected an integer, found 'one'"},
        ErrorCase{"UnknownRecord", kHeader + "\nsplash 1 2\n",
                  "bad.strokes:3: unknown record 'splash'"},
        ErrorCase{"NanTime", kHeader + "pen nan 0 0 0 0 0 0 0\n",
                  "bad.strokes:2: field 'time': 'nan' is not a finite number"},
        ErrorCase{"InfX", kHeader + "pen 0 inf 0 0 0 0 0 0\n",
                  "bad.strokes:2: field 'x': 'inf' is not a finite number"},
        ErrorCase{"NanPressure", kHeader + "pen 0 0 0 NaN 0 0 0 0\n",
                  "bad.strokes:2: field 'pressure': 'NaN' is not a finite number"},
        ErrorCase{"PressureAboveOne", kHeader + "pen 0 0 0 1.5 0 0 0 1\n",
                  "bad.strokes:2: field 'pressure': 1.5 is outside 0..1"},
        ErrorCase{"PressureNegative", kHeader + "pen 0 0 0 -0.25 0 0 0 1\n",
                  "bad.strokes:2: field 'pressure': -0.25 is outside 0..1"},
        ErrorCase{"TiltTooFar", kHeader + "pen 0 0 0 0 91 0 0 1\n",
                  "bad.strokes:2: field 'tilt_x': 91 is outside -90..90"},
        ErrorCase{"RotationTooFar", kHeader + "pen 0 0 0 0 0 0 361 1\n",
                  "bad.strokes:2: field 'rotation': 361 is outside 0..360"},
        ErrorCase{"ButtonsNegative", kHeader + "pen 0 0 0 0 0 0 0 -1\n",
                  "bad.strokes:2: field 'buttons': must be an unsigned 32-bit bit set"},
        ErrorCase{"TooFewPenFields", kHeader + "pen 0 0 0\n",
                  "bad.strokes:2: 'pen' takes 8 field(s): time x y pressure tilt_x tilt_y "
                  "rotation buttons, found 3"},
        ErrorCase{"UnknownBody", kHeader + "load 5 \"White\" 1 body=gel\n",
                  "bad.strokes:2: field 'body': unknown paint body 'gel' (known: fluid, soft, "
                  "heavy, paste)"},
        ErrorCase{"QualityUnknown", kHeader + "quality quick\n",
                  "bad.strokes:2: field 'level': unknown quality 'quick' (expected exact, "
                  "balanced or fast)"},
        ErrorCase{"QualityMissing", kHeader + "quality\n",
                  "bad.strokes:2: 'quality' takes 1 field(s): level, found 0"},
        ErrorCase{"VarnishUnknownFinish", kHeader + "varnish shiny 0.05\n",
                  "bad.strokes:2: field 'finish': unknown finish 'shiny' (known: gloss, satin, "
                  "matte)"},
        ErrorCase{"VarnishTooThick", kHeader + "varnish gloss 2\n",
                  "bad.strokes:2: field 'thickness': 2 mm is outside [1e-04, 1]"},
        ErrorCase{"VarnishNoThickness", kHeader + "varnish gloss 0\n",
                  "bad.strokes:2: field 'thickness': 0 mm is outside [1e-04, 1]"},
        ErrorCase{"VarnishDenormalThickness", kHeader + "varnish gloss 1e-320\n",
                  "bad.strokes:2: field 'thickness': 1e-320 mm is outside [1e-04, 1]"},
        ErrorCase{"VarnishHalfARegion", kHeader + "varnish gloss 0.05 1 2\n",
                  "bad.strokes:2: 'varnish' takes a finish and a thickness in mm, then "
                  "optionally a region x y width height in cells; found 4 field(s)"},
        ErrorCase{"VarnishEmptyRegion", kHeader + "varnish matte 0.05 1 2 0 4\n",
                  "bad.strokes:2: field 'width': 0 is outside 1..65536"},
        ErrorCase{"VarnishNegativeRegion", kHeader + "varnish matte 0.05 -1 2 3 4\n",
                  "bad.strokes:2: field 'x': -1 is outside 0..65536"},
        ErrorCase{"UnknownMedium", kHeader + "load 5 \"White\" 1 medium=shiny\n",
                  "bad.strokes:2: field 'medium': unknown finish 'shiny' (known: gloss, satin, "
                  "matte)"},
        ErrorCase{"MediumAmountOutOfRange",
                  kHeader + "load 5 \"White\" 1 medium=matte:1.5 body=soft\n",
                  "bad.strokes:2: field 'medium': the amount of medium '1.5' is not a number in "
                  "[0, 1]"},
        ErrorCase{"Garbage", kHeader + "pen 0 1x 0 0 0 0 0 0\n",
                  "bad.strokes:2: field 'x': expected a number, found '1x'"},
        ErrorCase{"TimeBackwards", kHeader + "pen 1 0 0 0 0 0 0 0\npen 0.5 0 0 0 0 0 0 0\n",
                  "bad.strokes:3: field 'time': time goes backwards (0.5 s after 1 s)"},
        ErrorCase{"CanvasTwice", kHeader + "canvas 10 10 300\ncanvas 10 10 300\n",
                  "bad.strokes:3: a second 'canvas' record"},
        ErrorCase{"CanvasAfterSamples", kHeader + "pen 0 0 0 0 0 0 0 0\ncanvas 10 10 300\n",
                  "bad.strokes:3: 'canvas' must come before the first pen sample"},
        ErrorCase{"CanvasAbsurdSize", kHeader + "canvas 100000000 10 300\n",
                  "bad.strokes:2: field 'width': 100000000 is outside 1..65536"},
        ErrorCase{"CanvasZeroDpi", kHeader + "canvas 10 10 0\n",
                  "bad.strokes:2: field 'dpi': must be positive"},
        ErrorCase{"ToolWithSpace", kHeader + "tool palette knife\n",
                  "bad.strokes:2: 'tool' takes 1 field(s): name, found 2"},
        ErrorCase{"BrushNoSize", kHeader + "brush round stiffness=0.5\n",
                  "bad.strokes:2: field 'size': missing (size=MM)"},
        ErrorCase{"BrushBadStiffness", kHeader + "brush round size=2 stiffness=2\n",
                  "bad.strokes:2: field 'stiffness': 2 is outside 0..1"},
        ErrorCase{"BrushNotKeyValue", kHeader + "brush round size=2 stiffness=0 soft\n",
                  "bad.strokes:2: field 'soft': expected key=value"},
        ErrorCase{"BrushKeyTwice", kHeader + "brush round size=2 size=3 stiffness=0\n",
                  "bad.strokes:2: field 'size': given twice"},
        ErrorCase{"BrushNanParam", kHeader + "brush round size=2 stiffness=0 splay=nan\n",
                  "bad.strokes:2: field 'splay': 'nan' is not a finite number"},
        ErrorCase{"LoadUnquoted", kHeader + "load 3 Titanium 1\n",
                  "bad.strokes:2: field 'pigment': pigment names are written in double quotes"},
        ErrorCase{"LoadOddFields", kHeader + "load 3 \"White\" 1 \"Ivory Black\"\n",
                  "bad.strokes:2: 'load' takes a volume in mm^3 then \"pigment name\" parts "
                  "pairs"},
        ErrorCase{"LoadUnterminated", kHeader + "load 3 \"White 1\n",
                  "bad.strokes:2: unterminated quoted name"},
        ErrorCase{"LoadNegativeVolume", kHeader + "load -3 \"White\" 1\n",
                  "bad.strokes:2: field 'volume': must be in [0, 1e+09] mm^3"},
        // The engine's range, refused when the file is read (the replay refused it before).
        ErrorCase{"LoadHugeVolume", kHeader + "load 2e9 \"White\" 1\n",
                  "bad.strokes:2: field 'volume': must be in [0, 1e+09] mm^3"},
        ErrorCase{"LoadZeroParts", kHeader + "load 3 \"White\" 0\n",
                  "bad.strokes:2: field 'parts': must be positive"},
        ErrorCase{"DryTooMuch", kHeader + "dry 1.5\n",
                  "bad.strokes:2: field 'fraction': 1.5 is outside 0..1"},
        ErrorCase{"UndoWithArgument", kHeader + "undo 3\n",
                  "bad.strokes:2: 'undo' takes 0 field(s): none, found 1"}),
    [](const ::testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(StrokeErrors, ErrorCarriesItsParts) {
  std::istringstream in(kHeader + "pen 0 0 0 2 0 0 0 0\n");
  try {
    parse_strokes(in, "parts.strokes");
    FAIL() << "no error";
  } catch (const InputFormatError& e) {
    EXPECT_EQ(e.source(), "parts.strokes");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "pressure");
  }
}

TEST(StrokeErrors, MissingFileIsNamed) {
  try {
    read_stroke_file("/nonexistent/dir/x.strokes");
    FAIL() << "no error";
  } catch (const InputFormatError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "/nonexistent/dir/x.strokes: cannot open the stroke file (No such file or directory)");
  }
}

}  // namespace
}  // namespace impasto::input
