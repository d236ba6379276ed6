// The tablet model table (data/tablets/models.tsv): it reads, its rows are sane, models that
// share USB ids are told apart by their device string, and a capture made with a handshake
// replays through the same decoder as the live tablet.
#include <impasto/input/hid_capture.hpp>
#include <impasto/input/hid_models.hpp>
#include <impasto/input/hid_tablet.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "hid_test_files.hpp"

namespace impasto::input::hid {
namespace {

using test::kM708;

const std::string kTable = IMPASTO_SOURCE_DIR "/data/tablets/models.tsv";

InitExchange with_string(std::uint8_t index, const std::string& text) {
  std::vector<std::uint8_t> bytes{static_cast<std::uint8_t>(2 + 2 * text.size()), 3};
  for (char c : text) {
    bytes.push_back(static_cast<std::uint8_t>(c));
    bytes.push_back(0);
  }
  InitExchange init;
  init.strings.push_back({index, bytes});
  return init;
}

TEST(TabletModels, TheTableReadsAndEveryRowIsSane) {
  const std::vector<TabletModel> models = load_tablet_models(kTable);
  EXPECT_GE(models.size(), 20u);
  std::set<std::string> sources;
  for (const TabletModel& m : models) {
    EXPECT_FALSE(m.name.empty());
    sources.insert(m.source.substr(0, m.source.find(':')));
    // The extents and the area agree on the resolution within a few percent of a common
    // one (100 or 200 lines per mm, 4000 or 5080 lines per inch).
    const double lines_per_mm_x = m.max_x / m.width_mm;
    const double lines_per_mm_y = m.max_y / m.height_mm;
    EXPECT_NEAR(lines_per_mm_x / lines_per_mm_y, 1.0, 0.01) << m.name;
  }
  EXPECT_EQ(sources, (std::set<std::string>{"digimend", "opentabletdriver"}));
}

TEST(TabletModels, SharedIdsAreToldApartByTheDeviceString) {
  const std::vector<TabletModel> models = load_tablet_models(kTable);
  EXPECT_GE(find_tablet_models(models, 0x256C, 0x006D).size(), 3u);  // unknown: all of them
  const auto kamvas =
      find_tablet_models(models, 0x256C, 0x006D, with_string(0xC9, "HUION_M182_230101"));
  ASSERT_EQ(kamvas.size(), 1u);
  EXPECT_EQ(kamvas[0].name, "Huion Kamvas Pro 13");
  EXPECT_NEAR(kamvas[0].width_mm, 293.76, 1e-9);
  const auto h1060p =
      find_tablet_models(models, 0x256C, 0x006D, with_string(0xC9, "HUION_T205_190101"));
  ASSERT_EQ(h1060p.size(), 1u);
  EXPECT_EQ(h1060p[0].name, "Huion H1060P");
  EXPECT_EQ(h1060p[0].vendor_format()->protocol, VendorProtocol::kUcLogicV2);  // reads 0xC8
  EXPECT_TRUE(find_tablet_models(models, 0x1234, 0x5678).empty());
}

TEST(TabletModels, ErrorsNameTheLineAndField) {
  const auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      parse_tablet_models(in, "t.tsv");
    } catch (const InputFormatError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string ok =
      "256c\t006e\tuclogic\tno\t254\t158.75\t40000\t25000\t2047\tstring:64\t-\t\"H610\"\tx";
  EXPECT_EQ(error_of(ok + "\n"), "no error");
  EXPECT_EQ(error_of("# c\n" + ok.substr(0, ok.size() - 2) + "\n"),
            "t.tsv:2: expected 13 columns (see the header), found 12");
  std::string bad = ok;
  bad.replace(bad.find("uclogic"), 7, "magic");
  EXPECT_EQ(error_of(bad), "t.tsv:1: field 'protocol': unknown protocol 'magic'");
  bad = ok;
  bad.replace(bad.find("string:64"), 9, "output:0");
  EXPECT_NE(error_of(bad).find("field 'init'"), std::string::npos);
}

// `hid record` stores the handshake with the reports: the capture replays through the decoder
// the live tablet had.
TEST(CaptureReplay, AHandshakeInTheCaptureDecodesLikeTheLiveTablet) {
  std::ifstream probe_file(kM708 + "probe.txt");
  const std::string probe((std::istreambuf_iterator<char>(probe_file)),
                          std::istreambuf_iterator<char>());
  HidRecording capture;
  capture.descriptor = read_descriptor_file(kM708 + "rd/original1.txt").bytes;
  capture.vendor_id = 0x28BD;
  capture.product_id = 0x0907;
  capture.init = parse_string_probe(probe, "probe.txt");
  capture.reports = read_report_file(kM708 + "dumps/pen_pressure.txt").reports;
  std::ostringstream out;
  write_hid_recording(out, capture);
  std::istringstream in(out.str());
  const HidRecording replayed = parse_hid_recording(in, "capture");
  EXPECT_EQ(replayed.init.strings, capture.init.strings);  // what the decoder reads

  const TabletDecoder live(capture.descriptor, capture.vendor_id, capture.product_id, capture.init,
                           load_tablet_models(kTable));
  EXPECT_TRUE(live.vendor_format().has_value());
  const auto samples = decode_recording(replayed);
  std::vector<paintcore::PenSample> expected;
  for (const RecordedReport& r : capture.reports) {
    if (auto s = live.decode(r.bytes, r.time_s)) expected.push_back(*s);
  }
  ASSERT_EQ(samples.size(), expected.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].time_s, expected[i].time_s, 1e-6);  // written with 6 decimals
    EXPECT_EQ(samples[i].x_mm, expected[i].x_mm);
    EXPECT_EQ(samples[i].pressure, expected[i].pressure);
    EXPECT_EQ(samples[i].buttons, expected[i].buttons);
  }
}

}  // namespace
}  // namespace impasto::input::hid
