// Pen samples from hand-made reports of real tablets' descriptors: positions in mm from the
// physical extents, pressure 0..1, tilt in degrees, switches to PenSample button bits.
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/hid_recording.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include "hid_test_files.hpp"

namespace impasto::input::hid {
namespace {

using test::kFiles;

using Bytes = std::vector<std::uint8_t>;
using paintcore::PenSample;

PenDecoder decoder_for(const std::string& stem) {
  const std::string path = kFiles + stem + ".rdesc.bin";
  return PenDecoder(parse_report_descriptor(load_descriptor_bytes(path), path));
}

void put16(Bytes& report, std::size_t at, int value) {
  report[at] = static_cast<std::uint8_t>(value & 0xFF);
  report[at + 1] = static_cast<std::uint8_t>((value >> 8) & 0xFF);
}

TEST(PenDecoder, HuionReport) {
  const PenDecoder pen = decoder_for("huion_inspiroy_h1060p__256C_006D__0010");
  // ID 10; byte 1: tip (bit 0), barrel (1), eraser (2), invert (3..5), in range (6);
  // X, Y, pressure 16 bits; tilt x, y 8 bits signed.
  Bytes report(10, 0);
  report[0] = 10;
  report[1] = 0x01 | 0x02 | 0x40;
  put16(report, 2, 16384);
  put16(report, 4, 8192);
  put16(report, 6, 4095);
  report[8] = static_cast<std::uint8_t>(-20);
  report[9] = 35;
  const auto s = pen.decode(report, 1.25);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->time_s, 1.25);
  // No length unit: 100 logical units per mm.
  EXPECT_DOUBLE_EQ(s->x_mm, 163.84);
  EXPECT_DOUBLE_EQ(s->y_mm, 81.92);
  EXPECT_FLOAT_EQ(s->pressure, 4095.0f / 8191.0f);
  EXPECT_FLOAT_EQ(s->tilt_x_deg, -20.0f);
  EXPECT_FLOAT_EQ(s->tilt_y_deg, 35.0f);
  EXPECT_EQ(s->buttons, paintcore::kPenTip | paintcore::kPenBarrel1 | paintcore::kPenInRange);

  report[1] = 0x08 | 0x40;  // invert: the eraser end, hovering
  const auto eraser = pen.decode(report, 1.5);
  EXPECT_EQ(eraser->buttons, paintcore::kPenEraser | paintcore::kPenInRange);
  report[1] = 0x00;
  EXPECT_EQ(pen.decode(report, 1.75)->buttons, 0u);  // out of range
}

// A tablet that sends more pressure than its descriptor declares (an XP-Pen Deco 01 v2 in
// its default mode: up to 8191 where it says 2047): the first value past the declared
// maximum grows the range for good, so a firm press is no longer the same as a light one.
TEST(PenDecoder, PressurePastTheDeclaredMaximumGrowsTheRange) {
  const std::string path = kFiles + "huion_inspiroy_h1060p__256C_006D__0010.rdesc.bin";
  std::vector<std::uint8_t> bytes = load_descriptor_bytes(path);
  // Tip Pressure's Logical Maximum 8191 (26 ff 1f) declared as 2047 (26 ff 07).
  const Bytes pressure_max{0x09, 0x30, 0x26, 0xff, 0x1f};
  const auto at = std::search(bytes.begin(), bytes.end(), pressure_max.begin(), pressure_max.end());
  ASSERT_NE(at, bytes.end());
  at[4] = 0x07;
  const auto report_with = [](int pressure) {
    Bytes report(10, 0);
    report[0] = 10;
    report[1] = 0x01 | 0x40;
    put16(report, 6, pressure);
    return report;
  };
  {
    const PenDecoder pen(parse_report_descriptor(bytes, path));
    EXPECT_EQ(pen.pressure_max(), 2047);
    EXPECT_FLOAT_EQ(pen.decode(report_with(2047), 0.0)->pressure, 1.0f);  // as declared
    EXPECT_FLOAT_EQ(pen.decode(report_with(6000), 0.1)->pressure, 6000.0f / 8191.0f);
    EXPECT_EQ(pen.pressure_max(), 8191);  // 2^13 - 1: the smallest that holds 6000
    EXPECT_FLOAT_EQ(pen.decode(report_with(2047), 0.2)->pressure, 2047.0f / 8191.0f);
    EXPECT_FLOAT_EQ(pen.decode(report_with(8191), 0.3)->pressure, 1.0f);
  }
  {
    // With the model table's levels, the first value past 2047 goes straight to them.
    DecoderOptions options;
    options.known_max_pressure = 8191;
    const PenDecoder pen(parse_report_descriptor(bytes, path), options);
    EXPECT_FLOAT_EQ(pen.decode(report_with(3000), 0.0)->pressure, 3000.0f / 8191.0f);
    EXPECT_EQ(pen.pressure_max(), 8191);
  }
}

TEST(PenDecoder, WacomOneReportInPhysicalUnits) {
  const PenDecoder pen = decoder_for("wacom_one_pen_tablet_small__056A_03CB__000A");
  const PenReportLayout& layout = pen.layouts().at(0);
  Bytes report(layout.bytes, 0);
  report[0] = 6;
  // Byte 1: contact count; byte 2: tip, barrel, barrel2, pad, eraser, invert, in range.
  report[2] = 0x01 | 0x04 | 0x40;
  put16(report, 3, 14688);   // X: half of 29376 -> 146.88 mm
  put16(report, 6, 16524);   // Y: the far edge -> 165.24 mm
  put16(report, 9, 4095);    // full pressure
  put16(report, 11, 4500);   // X tilt 45.00 degrees
  put16(report, 13, -3000);  // Y tilt -30.00 degrees
  const auto s = pen.decode(report, 0.0);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->x_mm, 146.88, 1e-9);
  EXPECT_NEAR(s->y_mm, 165.24, 1e-9);
  EXPECT_FLOAT_EQ(s->pressure, 1.0f);
  EXPECT_FLOAT_EQ(s->tilt_x_deg, 45.0f);
  EXPECT_FLOAT_EQ(s->tilt_y_deg, -30.0f);
  EXPECT_EQ(s->buttons, paintcore::kPenTip | paintcore::kPenBarrel2 | paintcore::kPenInRange);
}

TEST(PenDecoder, OtherReportsAreNotPenSamples) {
  const PenDecoder pen = decoder_for("wacom_one_pen_tablet_small__056A_03CB__000A");
  EXPECT_FALSE(pen.decode(Bytes{254, 0x01}, 0.0).has_value());  // system control
  EXPECT_FALSE(pen.decode(Bytes{}, 0.0).has_value());
  EXPECT_THROW(pen.decode(Bytes{6, 0, 0}, 0.0), InputFormatError);  // short pen report
}

TEST(PenDecoder, TwistAndUnitlessPressure) {
  // A minimal pen: X, Y in 0.1 mm (cm x10^-2), twist 0..359 degrees, no tip switch.
  const Bytes bytes = {
      0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01,              // Digitizer Pen application
      0x05, 0x01, 0x09, 0x30, 0x09, 0x31,              // X, Y
      0x65, 0x11, 0x55, 0x0E,                          // cm, exponent -2
      0x15, 0x00, 0x26, 0xE8, 0x03, 0x46, 0xE8, 0x03,  // logical and physical 0..1000
      0x75, 0x10, 0x95, 0x02, 0x81, 0x02, 0x05, 0x0D,
      0x09, 0x41, 0x65, 0x14, 0x55, 0x00, 0x95, 0x01,  // Twist in degrees
      0x26, 0x67, 0x01, 0x46, 0x67, 0x01, 0x81, 0x02,  // 0..359
      0x09, 0x30, 0x65, 0x00, 0x26, 0xFF, 0x00, 0x46,
      0xFF, 0x00, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02,  // Tip Pressure 0..255
      0xC0};
  const PenDecoder pen(parse_report_descriptor(bytes));
  EXPECT_NEAR(pen.area().width_mm, 100.0, 1e-9);
  Bytes report = {0xF4, 0x01, 0x64, 0x00, 0x5A, 0x00, 0x00};
  auto s = pen.decode(report, 0.0);
  EXPECT_NEAR(s->x_mm, 50.0, 1e-9);
  EXPECT_NEAR(s->y_mm, 10.0, 1e-9);
  EXPECT_FLOAT_EQ(s->rotation_deg, 90.0f);
  EXPECT_EQ(s->buttons, paintcore::kPenInRange);  // no pressure: hovering
  report[6] = 51;
  s = pen.decode(report, 0.0);
  EXPECT_FLOAT_EQ(s->pressure, 0.2f);
  EXPECT_EQ(s->buttons, paintcore::kPenTip | paintcore::kPenInRange);
}

TEST(PenDecoder, NoPenIsUnsupported) {
  const Bytes mouse = {0x05, 0x01, 0x09, 0x02, 0xA1, 0x01, 0x09, 0x30, 0x09,
                       0x31, 0x75, 0x08, 0x95, 0x02, 0x81, 0x06, 0xC0};
  const ReportDescriptor d = parse_report_descriptor(mouse);
  EXPECT_EQ(unsupported_reason(d),
            "it has no pen report (X and Y in a Digitizer Pen or Stylus collection, or absolute "
            "X, Y and Tip Pressure or Tip Switch in any other)");
  EXPECT_THROW(PenDecoder{d}, UnsupportedTablet);
}

}  // namespace
}  // namespace impasto::input::hid
