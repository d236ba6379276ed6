// The importers against the real recordings in tests/data/files/strokes (copies of the team's
// reference data).
#include <impasto/input/stroke_import.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace impasto::input {
namespace {

using paintcore::PenSample;

const std::string kStrokes = IMPASTO_TEST_FILES_DIR "/strokes/";

TEST(MypaintImport, RealPaintingHasAllEventsAndStrokes) {
  const auto samples = pen_samples(load_strokes_any(kStrokes + "libmypaint_painting30sec.dat"));
  ASSERT_EQ(samples.size(), 2937u);
  EXPECT_EQ(split_strokes(samples).size(), 30u);
  // First line: 0 205.244514 210.034483 0, at 150 px per inch.
  const double mm_per_px = 25.4 / 150.0;
  EXPECT_EQ(samples.front().time_s, 0.0);
  EXPECT_DOUBLE_EQ(samples.front().x_mm, 2.052445140000000094e+02 * mm_per_px);
  EXPECT_DOUBLE_EQ(samples.front().y_mm, 2.100344829999999945e+02 * mm_per_px);
  EXPECT_EQ(samples.front().pressure, 0.0f);
  EXPECT_EQ(samples.front().buttons, paintcore::kPenInRange);
  // Last line: 29.999 719.978056 110.034483 0.221135: still pressing.
  EXPECT_DOUBLE_EQ(samples.back().time_s, 2.999899999999999878e+01);
  EXPECT_DOUBLE_EQ(samples.back().x_mm, 7.199780560000000378e+02 * mm_per_px);
  EXPECT_DOUBLE_EQ(samples.back().y_mm, 1.100344829999999945e+02 * mm_per_px);
  EXPECT_FLOAT_EQ(samples.back().pressure, 0.221135f);
  EXPECT_TRUE(samples.back().tip_down());
}

TEST(MypaintImport, SourceDpiScalesPositions) {
  ImportOptions options;
  options.source_dpi = 25.4;  // one pixel per mm
  std::istringstream in("0 10 20 0.5\n0.01 11 21 0\n");
  const auto samples = pen_samples(parse_mypaint_dat(in, "two.dat", options));
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_DOUBLE_EQ(samples[0].x_mm, 10.0);
  EXPECT_DOUBLE_EQ(samples[1].y_mm, 21.0);
  EXPECT_TRUE(samples[0].tip_down());
  EXPECT_FALSE(samples[1].tip_down());
}

TEST(MypaintImport, BadLinesAreNamed) {
  const auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      parse_mypaint_dat(in, "bad.dat");
    } catch (const InputFormatError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("0 1 2 0.5\n0.1 1 2\n"),
            "bad.dat:2: expected 4 columns (time x y pressure), found 3");
  EXPECT_EQ(error_of("0 1 nan 0.5\n"), "bad.dat:1: field 'y': 'nan' is not a finite number");
  EXPECT_EQ(error_of("0 1 2 1.5\n"), "bad.dat:1: field 'pressure': outside 0..1");
  EXPECT_EQ(error_of(""), "bad.dat: no samples");
}

TEST(BdalabImport, RealSignalHasAllSamples) {
  const auto samples = pen_samples(load_strokes_any(kStrokes + "bdalab_signal.svc"));
  ASSERT_EQ(samples.size(), 1378u);
  EXPECT_EQ(split_strokes(samples).size(), 5u);
  // The file's maximum pressure (0.929619) is full scale.
  const double full_scale = 0.929619;
  // First: 52.81 81.31 0 1 510 520 0
  EXPECT_DOUBLE_EQ(samples.front().x_mm, 52.81);
  EXPECT_DOUBLE_EQ(samples.front().y_mm, 81.31);
  EXPECT_EQ(samples.front().time_s, 0.0);
  EXPECT_TRUE(samples.front().tip_down());
  EXPECT_EQ(samples.front().pressure, 0.0f);
  const Tilt first = tilt_from_azimuth_altitude(51.0, 52.0);
  EXPECT_FLOAT_EQ(samples.front().tilt_x_deg, static_cast<float>(first.x_deg));
  EXPECT_FLOAT_EQ(samples.front().tilt_y_deg, static_cast<float>(first.y_deg));
  // Last: 78.275 68.835 11.731 1 1030 570 0.160313
  EXPECT_DOUBLE_EQ(samples.back().x_mm, 78.275);
  EXPECT_DOUBLE_EQ(samples.back().y_mm, 68.835);
  EXPECT_DOUBLE_EQ(samples.back().time_s, 11.731);
  EXPECT_FLOAT_EQ(samples.back().pressure, static_cast<float>(0.160313 / full_scale));
  float max_pressure = 0.0f;
  for (const PenSample& s : samples) max_pressure = std::max(max_pressure, s.pressure);
  EXPECT_EQ(max_pressure, 1.0f);
}

TEST(BdalabImport, GivenPressureMaximum) {
  ImportOptions options;
  options.pressure_max = 1024.0;
  std::istringstream in("1\n1 2 0 1 0 900 512\n");
  const auto samples = pen_samples(parse_bdalab_svc(in, "one.svc", options));
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_FLOAT_EQ(samples[0].pressure, 0.5f);
  EXPECT_NEAR(samples[0].tilt_x_deg, 0.0f, 1e-6);  // altitude 90 degrees: upright
  EXPECT_NEAR(samples[0].tilt_y_deg, 0.0f, 1e-6);
}

TEST(BdalabImport, CountMismatchAndBadColumns) {
  const auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      parse_bdalab_svc(in, "bad.svc");
    } catch (const InputFormatError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("3\n1 2 0 1 0 900 5\n"),
            "bad.svc:1: field 'count': declares 3 samples but the file has 1");
  EXPECT_EQ(error_of("1\n"), "bad.svc:1: field 'count': declares 1 samples but the file has 0");
  EXPECT_EQ(error_of("1\n1 2 0 1 0 900\n"),
            "bad.svc:2: expected 7 columns (x y time pen_down azimuth altitude pressure), found 6");
  EXPECT_EQ(error_of("1\n1 2 0 2 0 900 5\n"), "bad.svc:2: field 'pen_down': must be 0 or 1");
  EXPECT_EQ(error_of("1\n1 2 0 1 0 inf 5\n"),
            "bad.svc:2: field 'altitude': 'inf' is not a finite number");
  EXPECT_EQ(error_of("x\n"), "bad.svc:1: field 'count': expected an integer, found 'x'");
  EXPECT_EQ(error_of("1\n1 2 0 1 1e300 900 5\n"),
            "bad.svc:2: field 'azimuth': outside -3600..3600");
}

// Real .svc files in public datasets have a count one off from their lines: they load with a
// warning and use the lines present.
TEST(BdalabImport, CountOffByOneLoadsWithAWarning) {
  std::ifstream real(kStrokes + "bdalab_signal.svc");
  std::string first, rest, line;
  std::getline(real, first);
  while (std::getline(real, line)) rest += line + "\n";
  const std::int64_t lines = std::stoll(first);
  for (const std::int64_t declared : {lines - 1, lines + 1}) {
    std::istringstream in(std::to_string(declared) + "\n" + rest);
    const StrokeFile file = parse_bdalab_svc(in, "off.svc");
    EXPECT_EQ(pen_samples(file).size(), static_cast<std::size_t>(lines));
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_EQ(file.warnings[0], "off.svc:1: field 'count': declares " + std::to_string(declared) +
                                    " samples but the file has " + std::to_string(lines) +
                                    "; the " + std::to_string(lines) + " present are used");
  }
  std::istringstream exact(first + "\n" + rest);
  EXPECT_TRUE(parse_bdalab_svc(exact, "exact.svc").warnings.empty());
}

TEST(Tilt, LimitsOfAzimuthAndAltitude) {
  // Upright pen: no tilt whatever the azimuth.
  for (double az : {0.0, 45.0, 200.0}) {
    const Tilt t = tilt_from_azimuth_altitude(az, 90.0);
    EXPECT_NEAR(t.x_deg, 0.0, 1e-12);
    EXPECT_NEAR(t.y_deg, 0.0, 1e-12);
  }
  // Leaning 30 degrees from vertical towards +x (azimuth 90) and towards +y (azimuth 0).
  Tilt t = tilt_from_azimuth_altitude(90.0, 60.0);
  EXPECT_NEAR(t.x_deg, 30.0, 1e-12);
  EXPECT_NEAR(t.y_deg, 0.0, 1e-12);
  t = tilt_from_azimuth_altitude(0.0, 60.0);
  EXPECT_NEAR(t.x_deg, 0.0, 1e-12);
  EXPECT_NEAR(t.y_deg, 30.0, 1e-12);
  t = tilt_from_azimuth_altitude(180.0, 60.0);
  EXPECT_NEAR(t.y_deg, -30.0, 1e-12);
  // Diagonal: tan(tilt_x) = cos(alt) sin(az) / sin(alt).
  t = tilt_from_azimuth_altitude(45.0, 45.0);
  const double expected = std::atan(std::sqrt(0.5)) * 180.0 / M_PI;
  EXPECT_NEAR(t.x_deg, expected, 1e-12);
  EXPECT_NEAR(t.y_deg, expected, 1e-12);
}

TEST(LoadAny, UnknownKindIsAnError) {
  EXPECT_THROW(load_strokes_any(IMPASTO_TEST_FILES_DIR "/strokes/bdalab_LICENSE.MIT.txt"),
               InputFormatError);
}

}  // namespace
}  // namespace impasto::input
