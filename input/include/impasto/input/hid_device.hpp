#pragma once
// Tablets on this machine, through hidapi's hidraw backend: finding pen digitizers, reading
// their report descriptors, one reader thread per tablet feeding a SampleQueue, and
// periodic re-enumeration so tablets can be plugged in and out while painting.
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_tablet.hpp>
#include <impasto/input/sample_queue.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace impasto::input::hid {

// False when Impasto was built without hidapi: the functions below then find no devices
// and opening one throws.
bool hid_available();

struct HidDeviceInfo {
  std::string path;  // e.g. /dev/hidraw3
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string manufacturer;
  std::string product;
  int interface_number = -1;
};

// Every HID device hidapi sees, one entry per device node.
std::vector<HidDeviceInfo> enumerate_hid_devices();

// The report descriptor of a hidraw node: from sysfs (readable without access to the node),
// else with the HIDIOCGRDESC ioctl. Throws std::runtime_error naming the node.
std::vector<std::uint8_t> read_report_descriptor(const std::string& hidraw_path);

// A raw USB string descriptor (bLength, 3, UTF-16LE) of the USB device a hidraw node belongs
// to, read through usbfs (/dev/bus/usb/BBB/DDD, which needs write access). Throws
// std::runtime_error naming the node and why.
std::vector<std::uint8_t> read_usb_string_descriptor(const std::string& hidraw_path,
                                                     std::uint8_t index);

// The UC-Logic handshake of a Huion/Gaomon/XP-Pen/Ugee tablet: reads its firmware name
// (0xC9), its v2 parameters (0xC8) or, without them, its v1 parameters (0x64) — reading them
// switches the tablet to its full-resolution vendor reports — and its model name (0x79).
// Indices the device refuses are listed as unanswered; `error` gets why none could be read.
InitExchange uclogic_handshake(const std::string& hidraw_path, std::string* error = nullptr);

// A device whose descriptor declares a pen (or whose vendor protocol Impasto knows).
struct PenTabletInfo {
  HidDeviceInfo device;
  std::vector<std::uint8_t> descriptor;
  InitExchange init;                     // what its handshake answered (empty if none was made)
  std::string unsupported_reason;        // empty when Impasto can read the pen
  std::optional<TabletSummary> summary;  // vendor, model, protocol, area, levels, tilt
  bool readable = false;                 // whether this user may open the node (udev uaccess)
};

// Where find_pen_tablets looks: this machine (hidapi, sysfs, usbfs), or a fake one in tests.
struct HidSystem {
  std::function<std::vector<HidDeviceInfo>()> enumerate;
  // Throws std::runtime_error when the descriptor cannot be read.
  std::function<std::vector<std::uint8_t>(const std::string& path)> read_descriptor;
  std::function<bool(const std::string& path)> readable;
  // The handshake of a UC-Logic vendor's device; unset: none is made.
  std::function<InitExchange(const HidDeviceInfo& device)> handshake;
  const std::vector<TabletModel>* models = nullptr;  // null: default_tablet_models()
};
// This machine; with `handshake`, UC-Logic vendors' tablets are asked for their parameters
// (which also switches them to their vendor reports, as their drivers do).
HidSystem this_machine(bool handshake = false);

// Pen digitizers among the HID devices: pen reports in any collection (or in Wacom's vendor
// page), tablets the model table or a handshake describes, and tablet makers' devices with
// vendor-defined collections (listed as unsupported, with the reason).
std::vector<PenTabletInfo> find_pen_tablets(const HidSystem& system);
std::vector<PenTabletInfo> find_pen_tablets();

// An open HID device; closed on destruction.
class HidDevice {
 public:
  explicit HidDevice(const std::string& path);  // throws std::runtime_error naming the path
  ~HidDevice();
  HidDevice(const HidDevice&) = delete;
  HidDevice& operator=(const HidDevice&) = delete;

  // One input report, or an empty vector after `timeout_ms` without one. Throws
  // std::runtime_error when the device is gone.
  std::vector<std::uint8_t> read(int timeout_ms);
  // Sends an output report (its first byte the report ID). Throws std::runtime_error.
  void write(const std::vector<std::uint8_t>& report);

 private:
  void* handle_ = nullptr;
  std::string path_;
};

// What a tablet needs before it reports at full resolution, done on the open device: the
// model table's output reports sent (XP-Pen, Veikk) and strings read, or the UC-Logic
// handshake for UC-Logic vendors. Returns the exchange, for the decoder and for captures.
InitExchange initialise_tablet(const HidDeviceInfo& device, HidDevice& open_device,
                               const std::vector<TabletModel>& models, std::string* error);

// Reads one tablet on its own thread, decoding reports into the queue. Times are seconds
// since `origin` (steady clock), the same for every tablet of a session.
class TabletReader {
 public:
  TabletReader(PenTabletInfo tablet, SampleQueue& queue,
               std::chrono::steady_clock::time_point origin);
  ~TabletReader();  // stops and joins the thread
  TabletReader(const TabletReader&) = delete;
  TabletReader& operator=(const TabletReader&) = delete;

  const PenTabletInfo& tablet() const { return tablet_; }
  // The pen's active area in mm (what a mapping onto the screen or canvas needs).
  TabletArea area() const { return decoder_.area(); }
  bool running() const { return running_.load(); }
  // Why the thread stopped (unplugged, no permission, ...), empty while it runs.
  std::string stop_reason() const;
  std::size_t bad_reports() const { return bad_reports_.load(); }

 private:
  void run();

  PenTabletInfo tablet_;
  TabletDecoder decoder_;
  SampleQueue& queue_;
  std::chrono::steady_clock::time_point origin_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> running_{true};
  std::atomic<std::size_t> bad_reports_{0};
  mutable std::mutex reason_mutex_;
  std::string stop_reason_;
  std::thread thread_;
};

// A tablet being read, as the application lists and maps it.
struct ConnectedTablet {
  std::string path;  // e.g. /dev/hidraw3
  std::string name;  // manufacturer and product, as the device reports them
  TabletArea area;   // the pen's active area, mm
};

// The samples one tablet produced since the last poll, in tablet mm.
struct TabletSamples {
  ConnectedTablet tablet;
  std::vector<paintcore::PenSample> samples;
};

// Every readable, supported tablet, re-enumerated periodically: plugged-in tablets start
// reading, unplugged ones are dropped. The application polls samples without blocking.
class TabletManager {
 public:
  explicit TabletManager(std::chrono::milliseconds rescan_interval = std::chrono::seconds(1));
  ~TabletManager();
  TabletManager(const TabletManager&) = delete;
  TabletManager& operator=(const TabletManager&) = delete;

  // Samples of all tablets since the last poll, oldest first; never blocks for long.
  std::vector<paintcore::PenSample> poll();
  // The same, kept apart per tablet with its active area, so that each tablet's mm can be
  // mapped with its own area. Tablets without new samples are left out.
  std::vector<TabletSamples> poll_tablets();
  // The device paths being read now.
  std::vector<std::string> connected() const;
  // The tablets being read now, with their names and active areas.
  std::vector<ConnectedTablet> tablets() const;
  // Seconds since this time are the samples' time_s (steady clock).
  std::chrono::steady_clock::time_point origin() const { return origin_; }

 private:
  // One tablet: its queue outlives its reader, whose thread pushes into it.
  struct Reading {
    std::unique_ptr<SampleQueue> queue;
    std::unique_ptr<TabletReader> reader;
  };
  void rescan();
  void run();

  std::chrono::steady_clock::time_point origin_ = std::chrono::steady_clock::now();
  std::chrono::milliseconds interval_;
  mutable std::mutex mutex_;
  std::vector<Reading> readers_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace impasto::input::hid
