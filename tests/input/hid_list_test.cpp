// `impasto hid list` against fake enumerations: which devices are listed, with which vendor,
// model, protocol, area, pressure levels and tilt, and why the others are unsupported. The
// descriptors and handshake answers are real (tests/data/files/hid).
#include <impasto/input/hid_capture.hpp>
#include <impasto/input/hid_describe.hpp>
#include <impasto/input/hid_device.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "hid_test_files.hpp"

namespace impasto::input::hid {
namespace {

using test::kFiles;
using test::models;
using test::read_text;

using Bytes = std::vector<std::uint8_t>;

struct FakeDevice {
  HidDeviceInfo info;
  std::optional<Bytes> descriptor;  // nullopt: cannot be read
  InitExchange handshake;
  bool readable = true;
};

HidSystem fake_system(const std::vector<FakeDevice>& devices) {
  HidSystem system;
  system.enumerate = [devices] {
    std::vector<HidDeviceInfo> list;
    for (const FakeDevice& d : devices) list.push_back(d.info);
    return list;
  };
  system.read_descriptor = [devices](const std::string& path) {
    for (const FakeDevice& d : devices) {
      if (d.info.path == path && d.descriptor) return *d.descriptor;
    }
    throw std::runtime_error(path + ": cannot read the report descriptor: Permission denied");
  };
  system.readable = [devices](const std::string& path) {
    for (const FakeDevice& d : devices) {
      if (d.info.path == path) return d.readable;
    }
    return false;
  };
  system.handshake = [devices](const HidDeviceInfo& device) {
    for (const FakeDevice& d : devices) {
      if (d.info.path == device.path) return d.handshake;
    }
    return InitExchange{};
  };
  system.models = &models();
  return system;
}

std::vector<FakeDevice> a_desk() {
  const std::string h610 = kFiles + "captures/Huion_H610/";
  const Bytes keyboard = {0x05, 0x01, 0x09, 0x06, 0xA1, 0x01, 0x05, 0x07, 0x19, 0xE0, 0x29, 0xE7,
                          0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x08, 0x81, 0x02, 0xC0};
  const Bytes vendor_only = {0x06, 0x00, 0xFF, 0x09, 0x01, 0xA1, 0x01, 0x85, 0x02,
                             0x09, 0x02, 0x75, 0x08, 0x95, 0x09, 0x81, 0x02, 0xC0};
  return {
      {{"/dev/hidraw0", 0x046D, 0xC31C, "Logitech", "Keyboard", 0}, keyboard, {}, true},
      {{"/dev/hidraw1", 0x056A, 0x0374, "Wacom Co.,Ltd.", "Intuos S", 0},
       read_descriptor_file(kFiles + "wacom_intuos_s_3rd_gen__056A_0374__000A.rdesc.bin").bytes,
       {},
       false},
      {{"/dev/hidraw2", 0x256C, 0x006E, "HUION", "PenTablet", 0},
       read_descriptor_file(h610 + "rd/original0.txt").bytes,
       parse_string_probe(read_text(h610 + "probe.txt"), "probe.txt"),
       true},
      {{"/dev/hidraw3", 0x28BD, 0x0999, "UGTABLET", "Unknown tablet", 2}, vendor_only, {}, true},
      {{"/dev/hidraw4", 0x256C, 0x0070, "HUION", "Locked", 0}, std::nullopt, {}, false},
  };
}

TEST(HidList, ListsTabletsWithTheirFields) {
  const std::vector<PenTabletInfo> tablets = find_pen_tablets(fake_system(a_desk()));
  std::map<std::string, const PenTabletInfo*> by_path;
  for (const PenTabletInfo& t : tablets) by_path[t.device.path] = &t;
  EXPECT_EQ(by_path.count("/dev/hidraw0"), 0u);  // a keyboard is not a tablet
  ASSERT_EQ(tablets.size(), 4u);

  const PenTabletInfo& wacom = *by_path.at("/dev/hidraw1");
  ASSERT_TRUE(wacom.summary.has_value()) << wacom.unsupported_reason;
  EXPECT_EQ(wacom.summary->vendor, "Wacom");
  EXPECT_EQ(wacom.summary->model, "Wacom CTL-4100");
  EXPECT_NE(wacom.summary->protocol.find("0xFF0D"), std::string::npos);
  EXPECT_NEAR(wacom.summary->width_mm, 152.0, 1e-9);
  EXPECT_NEAR(wacom.summary->height_mm, 95.0, 1e-9);
  EXPECT_EQ(wacom.summary->pressure_levels, 4096u);
  EXPECT_FALSE(wacom.summary->tilt);
  EXPECT_FALSE(wacom.readable);

  const PenTabletInfo& huion = *by_path.at("/dev/hidraw2");
  ASSERT_TRUE(huion.summary.has_value()) << huion.unsupported_reason;
  EXPECT_EQ(huion.summary->vendor, "Huion / Gaomon");
  EXPECT_EQ(huion.summary->model, "Huion H610");
  EXPECT_EQ(huion.summary->protocol, "UC-Logic v1 (handshake)");
  EXPECT_NEAR(huion.summary->width_mm, 254.0, 1e-9);
  EXPECT_NEAR(huion.summary->height_mm, 158.75, 1e-9);
  EXPECT_EQ(huion.summary->pressure_levels, 2048u);

  const PenTabletInfo& unknown = *by_path.at("/dev/hidraw3");
  EXPECT_FALSE(unknown.summary.has_value());
  EXPECT_NE(unknown.unsupported_reason.find("vendor-defined"), std::string::npos)
      << unknown.unsupported_reason;

  const PenTabletInfo& locked = *by_path.at("/dev/hidraw4");
  EXPECT_NE(locked.unsupported_reason.find("Permission denied"), std::string::npos);

  const std::string text = describe_tablet_list(tablets);
  EXPECT_NE(text.find("/dev/hidraw2  256c:006e  HUION PenTablet\n"
                      "  vendor: Huion / Gaomon  model: Huion H610\n"
                      "  protocol: UC-Logic v1 (handshake)  area: 254.00 x 158.75 mm  "
                      "pressure: 2048 levels  tilt: no\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("no permission to read /dev/hidraw1"), std::string::npos) << text;
  EXPECT_NE(text.find("/dev/hidraw3  28bd:0999  UGTABLET Unknown tablet\n  unsupported: "),
            std::string::npos)
      << text;
}

// An unknown model of a UC-Logic vendor is read from its handshake's answer.
TEST(HidList, UnknownModelOfAKnownVendorFallsBackToTheHandshake) {
  std::vector<FakeDevice> desk = a_desk();
  FakeDevice& unknown = desk[3];
  Bytes v2(18, 0);
  v2[0] = 18, v2[1] = 3;
  v2[2] = 0x60, v2[3] = 0xEA;    // x 60000
  v2[5] = 0x30, v2[6] = 0x75;    // y 30000
  v2[8] = 0xFF, v2[9] = 0x3F;    // pressure 16383
  v2[10] = 0xA0, v2[11] = 0x0F;  // 4000 lpi
  unknown.handshake.strings.push_back({0xC8, v2});
  const std::vector<PenTabletInfo> tablets = find_pen_tablets(fake_system(desk));
  const PenTabletInfo* t = nullptr;
  for (const PenTabletInfo& x : tablets) {
    if (x.device.path == "/dev/hidraw3") t = &x;
  }
  ASSERT_NE(t, nullptr);
  ASSERT_TRUE(t->summary.has_value()) << t->unsupported_reason;
  EXPECT_EQ(t->summary->model, "");
  EXPECT_EQ(t->summary->protocol, "UC-Logic v2 (handshake)");
  EXPECT_NEAR(t->summary->width_mm, 60000 * 25.4 / 4000, 1e-9);
  EXPECT_EQ(t->summary->pressure_levels, 16384u);
  EXPECT_TRUE(t->summary->tilt);
}

}  // namespace
}  // namespace impasto::input::hid
