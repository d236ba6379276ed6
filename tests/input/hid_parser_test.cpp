// Hand-written descriptors for the corners of HID 1.11 the real tablets do not reach.
#include <impasto/input/hid_descriptor.hpp>
#include <impasto/input/hid_report.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace impasto::input::hid {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::string error_of(const Bytes& bytes) {
  try {
    parse_report_descriptor(bytes, "fixture");
  } catch (const InputFormatError& e) {
    return e.what();
  }
  return "no error";
}

TEST(HidParser, EmptyDescriptorHasNothing) {
  const ReportDescriptor d = parse_report_descriptor({}, "empty");
  EXPECT_TRUE(d.fields.empty());
  EXPECT_TRUE(d.reports.empty());
  EXPECT_FALSE(d.has_report_ids);
}

TEST(HidParser, PushPopRestoresGlobals) {
  const Bytes bytes = {0x05, 0x01,                    // Usage Page (Generic Desktop)
                       0xA1, 0x01,                    // Collection (Application)
                       0x75, 0x08,                    //   Report Size (8)
                       0x95, 0x01,                    //   Report Count (1)
                       0x26, 0xFF, 0x00,              //   Logical Maximum (255)
                       0xA4,                          //   Push
                       0x05, 0x0D,                    //     Usage Page (Digitizer)
                       0x75, 0x10,                    //     Report Size (16)
                       0x27, 0xFF, 0xFF, 0x00, 0x00,  // Logical Maximum (65535), 4 bytes
                       0x09, 0x30,                    //     Usage (Tip Pressure)
                       0x81, 0x02,                    //     Input (Data, Var, Abs)
                       0xB4,                          //   Pop
                       0x09, 0x30,  //   Usage (X): the page is Generic Desktop again
                       0x81, 0x02,  //   Input
                       0xC0};       // End Collection
  const ReportDescriptor d = parse_report_descriptor(bytes);
  ASSERT_EQ(d.fields.size(), 2u);
  EXPECT_EQ(d.fields[0].usage_at(0), make_usage(0x0D, 0x30));
  EXPECT_EQ(d.fields[0].bit_size, 16u);
  EXPECT_EQ(d.fields[0].logical_max, 65535);
  EXPECT_EQ(d.fields[1].usage_at(0), usage::kX);
  EXPECT_EQ(d.fields[1].bit_size, 8u);
  EXPECT_EQ(d.fields[1].bit_offset, 16u);
  EXPECT_EQ(d.fields[1].logical_max, 255);
  EXPECT_EQ(d.reports.at(0).bits, 24u);
}

TEST(HidParser, PopWithoutPushIsAnError) {
  EXPECT_EQ(error_of({0x05, 0x01, 0xB4}), "fixture: field 'byte 2': Pop without Push");
}

TEST(HidParser, SignedFieldsAreSignExtended) {
  const Bytes bytes = {0x05, 0x0D, 0x09, 0x3D, 0x09, 0x3E,  // X Tilt, Y Tilt
                       0x15, 0x81,                          // Logical Minimum (-127)
                       0x25, 0x7F,                          // Logical Maximum (127)
                       0x75, 0x08, 0x95, 0x02, 0x81, 0x02,  // 8 bits x 2, Input
                       0x16, 0x00, 0xF0,                    // Logical Minimum (-4096)
                       0x26, 0xFF, 0x0F,                    // Logical Maximum (4095)
                       0x75, 0x0D, 0x95, 0x01,              // 13 bits x 1
                       0x09, 0x41, 0x81, 0x02};             // Twist, Input
  const ReportDescriptor d = parse_report_descriptor(bytes);
  ASSERT_EQ(d.fields.size(), 2u);
  EXPECT_EQ(d.fields[0].logical_min, -127);
  EXPECT_EQ(d.fields[1].logical_min, -4096);
  EXPECT_EQ(d.fields[1].logical_max, 4095);
  // Tilts -20 (0xEC) and 100; twist -1 in 13 bits (all ones) then 3 bits of padding.
  const Bytes report = {0xEC, 0x64, 0xFF, 0x1F};
  EXPECT_EQ(field_value(d.fields[0], 0, report), -20);
  EXPECT_EQ(field_value(d.fields[0], 1, report), 100);
  EXPECT_EQ(field_value(d.fields[1], 0, report), -1);
  const Bytes positive = {0, 0, 0xFF, 0x0F};  // 4095
  EXPECT_EQ(field_value(d.fields[1], 0, positive), 4095);
}

TEST(HidParser, UnsignedMaximumWhenMinimumIsNotNegative) {
  // Logical Maximum written as the single byte 0xFF means 255 when the minimum is 0.
  const Bytes bytes = {0x05, 0x01, 0x09, 0x30, 0x15, 0x00, 0x25,
                       0xFF, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  EXPECT_EQ(d.fields.at(0).logical_max, 255);
  EXPECT_FALSE(d.fields.at(0).is_signed());
  EXPECT_EQ(field_value(d.fields[0], 0, Bytes{0xFE}), 254);
}

TEST(HidParser, UsageRangesAndTheLastUsageRepeats) {
  const Bytes bytes = {0x05, 0x09,              // Usage Page (Button)
                       0x19, 0x01, 0x29, 0x03,  // Usage Minimum (1), Usage Maximum (3)
                       0x09, 0x07,              // Usage (Button 7)
                       0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95,
                       0x06, 0x81, 0x02, 0x95, 0x02, 0x81, 0x03};  // 2 bits of constant padding
  const ReportDescriptor d = parse_report_descriptor(bytes);
  ASSERT_EQ(d.fields.size(), 2u);
  const ReportField& buttons = d.fields[0];
  EXPECT_EQ(buttons.usage_count(), 4u);
  EXPECT_EQ(buttons.usage_at(0), make_usage(0x09, 1));
  EXPECT_EQ(buttons.usage_at(2), make_usage(0x09, 3));
  EXPECT_EQ(buttons.usage_at(3), make_usage(0x09, 7));
  EXPECT_EQ(buttons.usage_at(5), make_usage(0x09, 7));
  EXPECT_TRUE(d.fields[1].is_constant());
  EXPECT_EQ(d.reports.at(0).bits, 8u);
  const auto values = decode_usage_values(d, Bytes{0b00100101});
  ASSERT_EQ(values.size(), 6u);  // padding is not a value
  EXPECT_EQ(values[0], (UsageValue{make_usage(0x09, 1), 1}));
  EXPECT_EQ(values[1], (UsageValue{make_usage(0x09, 2), 0}));
  EXPECT_EQ(values[2], (UsageValue{make_usage(0x09, 3), 1}));
  EXPECT_EQ(values[5], (UsageValue{make_usage(0x09, 7), 1}));
}

TEST(HidParser, ArrayFieldsSelectUsages) {
  const Bytes bytes = {0x05, 0x07, 0x19, 0x04, 0x29, 0x06,  // Keyboard a..c
                       0x15, 0x00, 0x25, 0x02, 0x75, 0x08, 0x95, 0x02, 0x81, 0x00};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  EXPECT_FALSE(d.fields.at(0).is_variable());
  const auto values = decode_usage_values(d, Bytes{0x02, 0x07});  // c, then out of range
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], (UsageValue{make_usage(0x07, 0x06), 1}));
}

TEST(HidParser, ExtendedUsagesCarryTheirPage) {
  const Bytes bytes = {0x05, 0x01,                    // page Generic Desktop
                       0x0B, 0x30, 0x00, 0x0D, 0x00,  // Usage (Digitizer:Tip Pressure)
                       0x09, 0x31,                    // Usage (Y) on the current page
                       0x75, 0x08, 0x95, 0x02, 0x81, 0x02};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  EXPECT_EQ(d.fields.at(0).usage_at(0), usage::kTipPressure);
  EXPECT_EQ(d.fields.at(0).usage_at(1), usage::kY);
}

TEST(HidParser, LongItemsAreSkipped) {
  const Bytes bytes = {0xFE, 0x03, 0xF1, 0xAA, 0xBB, 0xCC,  // long item, 3 data bytes
                       0x05, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  ASSERT_EQ(d.fields.size(), 1u);
  EXPECT_EQ(d.fields[0].usage_at(0), usage::kX);
}

TEST(HidParser, ReportIdsSplitReports) {
  const Bytes bytes = {0x05, 0x01, 0x85, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81,
                       0x02, 0x85, 0x02, 0x09, 0x31, 0x75, 0x10, 0x81, 0x02, 0xB1, 0x02};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  EXPECT_TRUE(d.has_report_ids);
  ASSERT_NE(d.find_report(ReportType::kInput, 1), nullptr);
  EXPECT_EQ(d.find_report(ReportType::kInput, 1)->bytes(true), 2u);
  EXPECT_EQ(d.find_report(ReportType::kInput, 2)->bytes(true), 3u);
  EXPECT_EQ(d.find_report(ReportType::kFeature, 2)->bytes(true), 3u);
  EXPECT_EQ(d.fields[1].bit_offset, 0u);  // offsets restart in each report
  const auto values = decode_usage_values(d, Bytes{0x02, 0x34, 0x12});
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], (UsageValue{usage::kY, 0x1234}));
}

TEST(HidParser, NestedCollectionsAndApplication) {
  const Bytes bytes = {0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01,  // Pen application
                       0x09, 0x20, 0xA1, 0x00,              //   Stylus physical
                       0x09, 0x42, 0x75, 0x01, 0x95, 0x01, 0x81,
                       0x02, 0x75, 0x07, 0x81, 0x03, 0xC0, 0xC0};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  ASSERT_EQ(d.collections.size(), 2u);
  EXPECT_EQ(d.collections[1].parent, 0);
  EXPECT_EQ(d.collections[1].usage, usage::kStylus);
  EXPECT_EQ(d.fields.at(0).collection, 1);
  EXPECT_EQ(d.application_of(d.fields[0]), usage::kPen);
}

TEST(HidParser, UnitsToMillimetresAndDegrees) {
  EXPECT_DOUBLE_EQ(Unit({0x11, -3}).millimetres().value(), 0.01);  // 1e-3 cm
  EXPECT_DOUBLE_EQ(Unit({0x13, -3}).millimetres().value(), 0.0254);
  EXPECT_FALSE(Unit({0x33, -3}).millimetres().has_value());  // inch^3 is not a length
  EXPECT_FALSE(Unit({0x0, 0}).millimetres().has_value());
  EXPECT_DOUBLE_EQ(Unit({0x14, -2}).degrees().value(), 0.01);
  EXPECT_NEAR(Unit({0x12, 0}).degrees().value(), 57.29577951308232, 1e-12);
  EXPECT_EQ(Unit({0x11, -3}).name(), "cm x10^-3");
  // Unit Exponent item: 0x0D is the nibble -3; a signed byte 0xFD is also -3.
  const ReportDescriptor a = parse_report_descriptor(
      Bytes{0x55, 0x0D, 0x65, 0x11, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02});
  EXPECT_EQ(a.fields.at(0).unit.exponent, -3);
  const ReportDescriptor b = parse_report_descriptor(
      Bytes{0x56, 0xFD, 0xFF, 0x65, 0x11, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02});
  EXPECT_EQ(b.fields.at(0).unit.exponent, -3);
}

TEST(HidParser, MalformedDescriptorsAreNamedByByte) {
  EXPECT_EQ(error_of({0x05}), "fixture: field 'byte 0': truncated item (needs 1 data bytes)");
  EXPECT_EQ(error_of({0x05, 0x01, 0x27, 0x01}),
            "fixture: field 'byte 2': truncated item (needs 4 data bytes)");
  EXPECT_EQ(error_of({0xFE, 0x05, 0x10, 0x00}), "fixture: field 'byte 0': truncated long item");
  EXPECT_EQ(error_of({0xC0}), "fixture: field 'byte 0': End Collection without an open collection");
  EXPECT_EQ(error_of({0xA1, 0x01}), "fixture: field 'byte 2': 1 collection(s) not closed");
  EXPECT_EQ(error_of({0x85, 0x00}), "fixture: field 'byte 0': report ID must be 1..255");
  EXPECT_EQ(error_of({0x0C}), "fixture: field 'byte 0': reserved item type");
  EXPECT_EQ(error_of({0x19, 0x05, 0x29, 0x01}),
            "fixture: field 'byte 2': Usage Minimum is greater than Usage Maximum");
  EXPECT_EQ(error_of({0x76, 0x01, 0x01, 0x95, 0x01, 0x81, 0x02}),
            "fixture: field 'byte 5': report size 257 bits is over 256");
  // 256 bits x 65535: far beyond any real report.
  EXPECT_EQ(error_of({0x76, 0x00, 0x01, 0x96, 0xFF, 0xFF, 0x81, 0x02}),
            "fixture: field 'byte 6': report 0 is larger than 16384 bytes");
}

TEST(HidParser, ShortReportsAreRejectedLongOnesAccepted) {
  const Bytes bytes = {0x85, 0x03, 0x05, 0x01, 0x09, 0x30, 0x75, 0x10, 0x95, 0x02, 0x81, 0x02};
  const ReportDescriptor d = parse_report_descriptor(bytes);
  try {
    decode_usage_values(d, Bytes{0x03, 0x01, 0x02}, "dev");
    FAIL() << "no error";
  } catch (const InputFormatError& e) {
    EXPECT_EQ(std::string(e.what()),
              "dev: field 'length': input report 3 has 2 data bytes, the descriptor declares 4");
  }
  try {
    decode_usage_values(d, Bytes{0x04, 0, 0, 0, 0}, "dev");
    FAIL() << "no error";
  } catch (const InputFormatError& e) {
    EXPECT_EQ(std::string(e.what()), "dev: field 'report ID': no input report 4 in the descriptor");
  }
  EXPECT_THROW(decode_usage_values(d, Bytes{}, "dev"), InputFormatError);
  EXPECT_EQ(decode_usage_values(d, Bytes{0x03, 1, 0, 2, 0, 0xEE, 0xEE}).size(), 2u);
}

}  // namespace
}  // namespace impasto::input::hid
