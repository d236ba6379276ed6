// The device layer without hardware: errors name the node, threads start and stop cleanly.
#include <impasto/input/hid_device.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace impasto::input::hid {
namespace {

TEST(HidDevice, MissingNodeIsNamed) {
  try {
    read_report_descriptor("/dev/hidraw-impasto-missing");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/hidraw-impasto-missing"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(HidDevice("/dev/hidraw-impasto-missing"), std::runtime_error);
}

TEST(TabletReader, StopsWithAReasonWhenTheDeviceCannotBeOpened) {
  PenTabletInfo tablet;
  tablet.device.path = "/dev/hidraw-impasto-missing";
  tablet.device.vendor_id = 0x056A;
  tablet.device.product_id = 0x0061;  // a known vendor protocol: no descriptor needed
  SampleQueue queue;
  TabletReader reader(tablet, queue, std::chrono::steady_clock::now());
  for (int i = 0; i < 500 && reader.running(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_FALSE(reader.running());
  EXPECT_NE(reader.stop_reason().find("/dev/hidraw-impasto-missing"), std::string::npos)
      << reader.stop_reason();
  EXPECT_TRUE(queue.drain().empty());
}

TEST(TabletReader, UnsupportedTabletIsRefusedBeforeAThreadStarts) {
  PenTabletInfo tablet;
  tablet.device.path = "/dev/hidraw-impasto-missing";
  tablet.descriptor = {0x05, 0x01, 0x09, 0x02, 0xA1, 0x01, 0xC0};  // a mouse
  SampleQueue queue;
  EXPECT_THROW(TabletReader(tablet, queue, std::chrono::steady_clock::now()), UnsupportedTablet);
}

TEST(TabletManager, StartsScansAndStopsPromptly) {
  const auto start = std::chrono::steady_clock::now();
  {
    TabletManager manager(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    // Whatever this machine has, polling never blocks and only readers that run are listed.
    (void)manager.poll();
    (void)manager.connected();
  }
  // Destruction joins the scanning thread; it must not wait for a full interval or a read.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

}  // namespace
}  // namespace impasto::input::hid
