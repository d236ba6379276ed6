// The parser against real tablet descriptors (tests/data/files/hid). Expected values are read
// off the .hid-decode.txt listings; report sizes are the sums of Report Size x Report Count
// of each report's main items in those listings.
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/hid_recording.hpp>

#include <gtest/gtest.h>

#include <map>

#include "hid_test_files.hpp"

namespace impasto::input::hid {
namespace {

using test::kFiles;

ReportDescriptor load(const std::string& stem) {
  const std::string path = kFiles + stem + ".rdesc.bin";
  return parse_report_descriptor(load_descriptor_bytes(path), path);
}

std::map<int, std::uint32_t> input_report_bits(const ReportDescriptor& d) {
  std::map<int, std::uint32_t> bits;
  for (const ReportInfo& r : d.reports) {
    if (r.type == ReportType::kInput) bits[r.report_id] = r.bits;
  }
  return bits;
}

const ReportField& field_with(const ReportDescriptor& d, std::uint8_t report_id, Usage u) {
  for (const ReportField& f : d.fields) {
    if (f.type != ReportType::kInput || f.report_id != report_id) continue;
    for (std::uint32_t i = 0; i < f.count; ++i) {
      if (f.usage_at(i) == u) return f;
    }
  }
  throw std::runtime_error("no field with usage " + usage_name(u));
}

TEST(RealDescriptors, HexAndBinaryFilesAgree) {
  for (const char* stem :
       {"huion_inspiroy_h1060p__256C_006D__0010", "xp_pen_deco_pro_m__28BD_0904__000E",
        "wacom_one_pen_tablet_small__056A_03CB__000A",
        "wacom_intuos_pro_m_3rd_gen__056A_03F7__0008", "wacom_intuos_s_3rd_gen__056A_0374__000A"}) {
    EXPECT_EQ(load_descriptor_bytes(kFiles + stem + ".rdesc.hex"),
              load_descriptor_bytes(kFiles + stem + ".rdesc.bin"))
        << stem;
  }
}

TEST(RealDescriptors, HuionInspiroyH1060P) {
  const ReportDescriptor d = load("huion_inspiroy_h1060p__256C_006D__0010");
  EXPECT_TRUE(d.has_report_ids);
  EXPECT_EQ(input_report_bits(d), (std::map<int, std::uint32_t>{{10, 72}}));
  const ReportField& x = field_with(d, 10, usage::kX);
  EXPECT_EQ(x.bit_offset, 8u);
  EXPECT_EQ(x.bit_size, 16u);
  EXPECT_EQ(x.logical_max, 32767);
  EXPECT_EQ(x.physical_max, 2048);
  EXPECT_EQ(x.unit.code, 0x33u);  // "Inch^3" in the listing: no usable length
  EXPECT_EQ(x.unit.exponent, -3);
  EXPECT_FALSE(x.unit.millimetres().has_value());
  EXPECT_EQ(field_with(d, 10, usage::kTipPressure).logical_max, 8191);
  const ReportField& tilt = field_with(d, 10, usage::kXTilt);
  EXPECT_EQ(tilt.logical_min, -127);
  EXPECT_EQ(tilt.logical_max, 127);
  EXPECT_TRUE(tilt.is_signed());

  const PenDecoder pen(d);
  ASSERT_EQ(pen.layouts().size(), 1u);
  EXPECT_EQ(pen.layouts()[0].report_id, 10);
  EXPECT_EQ(pen.layouts()[0].bytes, 10u);
  EXPECT_FALSE(pen.area().from_descriptor);
}

TEST(RealDescriptors, XpPenDecoProM) {
  const ReportDescriptor d = load("xp_pen_deco_pro_m__28BD_0904__000E");
  EXPECT_EQ(input_report_bits(d), (std::map<int, std::uint32_t>{{7, 72}}));
  const ReportField& x = field_with(d, 7, usage::kX);
  EXPECT_EQ(x.logical_max, 32767);
  EXPECT_EQ(x.physical_max, 6181);  // set inside a Push .. Pop
  EXPECT_EQ(x.unit.code, 0x13u);    // inch
  EXPECT_EQ(x.unit.exponent, -3);
  const ReportField& y = field_with(d, 7, usage::kY);
  EXPECT_EQ(y.physical_max, 10984);
  // After Pop, the pressure field has the pre-Push unit (none) and physical extents.
  const ReportField& pressure = field_with(d, 7, usage::kTipPressure);
  EXPECT_EQ(pressure.unit.code, 0u);
  EXPECT_EQ(pressure.logical_max, 8191);
  EXPECT_TRUE(pressure.has_null_state());

  const PenDecoder pen(d);
  EXPECT_TRUE(pen.area().from_descriptor);
  EXPECT_NEAR(pen.area().width_mm, 6.181 * 25.4, 1e-9);
  EXPECT_NEAR(pen.area().height_mm, 10.984 * 25.4, 1e-9);
}

TEST(RealDescriptors, WacomOneSmall) {
  const ReportDescriptor d = load("wacom_one_pen_tablet_small__056A_03CB__000A");
  EXPECT_EQ(
      input_report_bits(d),
      (std::map<int, std::uint32_t>{
          {254, 8}, {6, 264}, {30, 264}, {80, 128}, {84, 384}, {85, 384}, {19, 64}, {172, 1528}}));
  const ReportField& x = field_with(d, 6, usage::kX);
  EXPECT_EQ(x.logical_max, 29376);
  EXPECT_EQ(x.unit.code, 0x11u);  // cm
  EXPECT_EQ(x.unit.exponent, -3);
  const ReportField& tilt = field_with(d, 6, usage::kYTilt);
  EXPECT_EQ(tilt.physical_min, -9000);
  EXPECT_EQ(tilt.unit.code, 0x14u);  // degrees
  EXPECT_EQ(tilt.unit.exponent, -2);
  EXPECT_DOUBLE_EQ(tilt.unit.degrees().value(), 0.01);

  const PenDecoder pen(d);
  ASSERT_EQ(pen.layouts().size(), 1u);  // report 30 is vendor-defined
  EXPECT_EQ(pen.layouts()[0].report_id, 6);
  EXPECT_EQ(pen.layouts()[0].bytes, 34u);
  EXPECT_NEAR(pen.area().width_mm, 293.76, 1e-9);
  EXPECT_NEAR(pen.area().height_mm, 165.24, 1e-9);
  EXPECT_TRUE(pen.layouts()[0].barrel2.present());
  EXPECT_TRUE(pen.layouts()[0].invert.present());
}

TEST(RealDescriptors, WacomIntuosProMGen3) {
  const ReportDescriptor d = load("wacom_intuos_pro_m_3rd_gen__056A_03F7__0008");
  EXPECT_EQ(input_report_bits(d),
            (std::map<int, std::uint32_t>{
                {254, 8}, {6, 136}, {30, 264}, {17, 64}, {19, 64}, {172, 1528}}));
  EXPECT_EQ(field_with(d, 6, usage::kX).logical_max, 26300);
  EXPECT_EQ(field_with(d, 6, usage::kY).logical_max, 14800);
  EXPECT_EQ(field_with(d, 6, usage::kTipPressure).logical_max, 4095);
  const PenDecoder pen(d);
  EXPECT_EQ(pen.layouts()[0].report_id, 6);
  EXPECT_EQ(pen.layouts()[0].bytes, 18u);
  EXPECT_NEAR(pen.area().width_mm, 263.0, 1e-9);
  EXPECT_NEAR(pen.area().height_mm, 148.0, 1e-9);
}

// Its pen is in Wacom's vendor page 0xFF0D: read through the usages Linux's wacom driver maps
// them to (0xFF0D0130 -> X, ...), report 16 spans 152 x 95 mm (cm, exponent -3).
TEST(RealDescriptors, WacomIntuosSGen3ThroughItsVendorPage) {
  const ReportDescriptor d = load("wacom_intuos_s_3rd_gen__056A_0374__000A");
  EXPECT_EQ(input_report_bits(d),
            (std::map<int, std::uint32_t>{{16, 208}, {17, 64}, {19, 64}, {172, 1528}}));
  EXPECT_EQ(unsupported_reason(d), "");
  const PenDecoder pen(d);
  EXPECT_TRUE(pen.wacom_vendor_page());
  ASSERT_EQ(pen.layouts().size(), 1u);  // the pad's report 17 has no X and Y
  EXPECT_EQ(pen.layouts()[0].report_id, 16);
  EXPECT_EQ(pen.layouts()[0].bytes, 27u);
  EXPECT_EQ(pen.layouts()[0].pressure.logical_max, 4095);
  EXPECT_TRUE(pen.layouts()[0].in_range.present());
  EXPECT_TRUE(pen.layouts()[0].barrel2.present());
  EXPECT_NEAR(pen.area().width_mm, 152.0, 1e-9);
  EXPECT_NEAR(pen.area().height_mm, 95.0, 1e-9);
}

}  // namespace
}  // namespace impasto::input::hid
