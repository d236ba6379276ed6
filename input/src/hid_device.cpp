#include <impasto/input/hid_device.hpp>

#include <impasto/input/hid_pen.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fcntl.h>
#include <unistd.h>

#include <linux/hidraw.h>
#include <sys/ioctl.h>

#ifdef IMPASTO_HAVE_HIDAPI
#include <hidapi/hidapi.h>
#endif

namespace impasto::input::hid {

namespace {

// Tablet makers whose vendor-defined collections are worth listing as unsupported pens.
constexpr std::uint16_t kTabletVendors[] = {0x056A /* Wacom */, 0x256C /* Huion */,
                                            0x28BD /* XP-Pen */, 0x5543 /* UC-Logic */};

std::mutex& hidapi_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::string narrow(const wchar_t* text) {
  std::string out;
  if (text == nullptr) return out;
  for (; *text != L'\0'; ++text) out += (*text < 0x80) ? static_cast<char>(*text) : '?';
  return out;
}

bool declares_pen(const ReportDescriptor& d) {
  for (const Collection& c : d.collections) {
    if (c.usage == usage::kPen || c.usage == usage::kStylus) return true;
  }
  return false;
}

bool is_tablet_vendor(std::uint16_t vendor) {
  return std::find(std::begin(kTabletVendors), std::end(kTabletVendors), vendor) !=
         std::end(kTabletVendors);
}

bool has_vendor_application(const ReportDescriptor& d) {
  for (const Collection& c : d.collections) {
    if (c.parent < 0 && usage_page(c.usage) >= page::kVendorFirst) return true;
  }
  return false;
}

}  // namespace

bool hid_available() {
#ifdef IMPASTO_HAVE_HIDAPI
  return true;
#else
  return false;
#endif
}

std::vector<HidDeviceInfo> enumerate_hid_devices() {
  std::vector<HidDeviceInfo> devices;
#ifdef IMPASTO_HAVE_HIDAPI
  const std::lock_guard lock(hidapi_mutex());
  if (hid_init() != 0) return devices;
  hid_device_info* list = hid_enumerate(0, 0);
  for (const hid_device_info* d = list; d != nullptr; d = d->next) {
    if (d->path == nullptr) continue;
    const std::string path = d->path;
    const bool seen = std::any_of(devices.begin(), devices.end(),
                                  [&](const HidDeviceInfo& e) { return e.path == path; });
    if (seen) continue;  // one entry per top-level collection: keep one per node
    devices.push_back({path, d->vendor_id, d->product_id, narrow(d->manufacturer_string),
                       narrow(d->product_string), d->interface_number});
  }
  hid_free_enumeration(list);
#endif
  return devices;
}

std::vector<std::uint8_t> read_report_descriptor(const std::string& hidraw_path) {
  const std::string node = std::filesystem::path(hidraw_path).filename().string();
  const std::filesystem::path sysfs =
      std::filesystem::path("/sys/class/hidraw") / node / "device" / "report_descriptor";
  if (std::ifstream in{sysfs, std::ios::binary}) {
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    if (!bytes.empty()) return bytes;
  }
  const int fd = ::open(hidraw_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(hidraw_path +
                             ": cannot read the report descriptor: " + std::strerror(errno));
  }
  int size = 0;
  hidraw_report_descriptor descriptor{};
  const bool ok =
      ::ioctl(fd, HIDIOCGRDESCSIZE, &size) == 0 && size > 0 && size <= HID_MAX_DESCRIPTOR_SIZE &&
      (descriptor.size = static_cast<__u32>(size), ::ioctl(fd, HIDIOCGRDESC, &descriptor) == 0);
  const int error = errno;
  ::close(fd);
  if (!ok) {
    throw std::runtime_error(hidraw_path + ": HIDIOCGRDESC failed: " + std::strerror(error));
  }
  return {descriptor.value, descriptor.value + size};
}

std::vector<PenTabletInfo> find_pen_tablets() {
  std::vector<PenTabletInfo> tablets;
  for (const HidDeviceInfo& device : enumerate_hid_devices()) {
    PenTabletInfo info;
    info.device = device;
    info.readable = ::access(device.path.c_str(), R_OK) == 0;
    try {
      info.descriptor = read_report_descriptor(device.path);
    } catch (const std::runtime_error& e) {
      // Only a tablet maker's device is worth reporting without its descriptor.
      if (!is_tablet_vendor(device.vendor_id)) continue;
      info.unsupported_reason = e.what();
      tablets.push_back(std::move(info));
      continue;
    }
    const bool known_protocol =
        find_graphire_tablet(device.vendor_id, device.product_id).has_value();
    try {
      const ReportDescriptor d = parse_report_descriptor(info.descriptor, device.path);
      const bool vendor_pen = is_tablet_vendor(device.vendor_id) && has_vendor_application(d);
      if (!known_protocol && !declares_pen(d) && !vendor_pen) continue;
      if (!known_protocol) info.unsupported_reason = unsupported_reason(d);
    } catch (const InputFormatError& e) {
      if (!known_protocol) {
        if (!is_tablet_vendor(device.vendor_id)) continue;
        info.unsupported_reason = std::string("malformed descriptor: ") + e.what();
      }
    }
    tablets.push_back(std::move(info));
  }
  return tablets;
}

HidDevice::HidDevice(const std::string& path) : path_(path) {
#ifdef IMPASTO_HAVE_HIDAPI
  const std::lock_guard lock(hidapi_mutex());
  if (hid_init() != 0) throw std::runtime_error("hidapi could not start");
  handle_ = hid_open_path(path.c_str());
  if (handle_ == nullptr) {
    throw std::runtime_error(path + ": cannot open (" + std::strerror(errno) +
                             "); see packaging/udev/70-impasto-tablets.rules");
  }
#else
  throw std::runtime_error(path + ": this impasto was built without hidapi");
#endif
}

HidDevice::~HidDevice() {
#ifdef IMPASTO_HAVE_HIDAPI
  if (handle_ != nullptr) hid_close(static_cast<hid_device*>(handle_));
#endif
}

std::vector<std::uint8_t> HidDevice::read(int timeout_ms) {
  std::vector<std::uint8_t> report;
#ifdef IMPASTO_HAVE_HIDAPI
  constexpr std::size_t kMaxReport = 16384;  // Linux's HID_MAX_BUFFER_SIZE
  report.resize(kMaxReport);
  const int n =
      hid_read_timeout(static_cast<hid_device*>(handle_), report.data(), report.size(), timeout_ms);
  if (n < 0) {
    throw std::runtime_error(
        path_ + ": read failed: " + narrow(hid_error(static_cast<hid_device*>(handle_))));
  }
  report.resize(static_cast<std::size_t>(n));
#else
  (void)timeout_ms;
#endif
  return report;
}

TabletReader::TabletReader(PenTabletInfo tablet, SampleQueue& queue,
                           std::chrono::steady_clock::time_point origin)
    : tablet_(std::move(tablet)),
      decoder_(tablet_.descriptor, tablet_.device.vendor_id, tablet_.device.product_id),
      queue_(queue),
      origin_(origin),
      thread_([this] { run(); }) {}

TabletReader::~TabletReader() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::string TabletReader::stop_reason() const {
  const std::lock_guard lock(reason_mutex_);
  return stop_reason_;
}

void TabletReader::run() {
  // A short timeout so that stopping never waits long for a silent tablet.
  constexpr int kReadTimeoutMs = 50;
  try {
    HidDevice device(tablet_.device.path);
    while (!stop_) {
      const std::vector<std::uint8_t> report = device.read(kReadTimeoutMs);
      if (report.empty()) continue;
      const double time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - origin_).count();
      try {
        if (auto sample = decoder_.decode(report, time_s)) queue_.push(*sample);
      } catch (const InputFormatError&) {
        ++bad_reports_;  // a short or unknown report: skip it, keep reading
      }
    }
  } catch (const std::exception& e) {
    const std::lock_guard lock(reason_mutex_);
    stop_reason_ = e.what();
  }
  running_ = false;
}

TabletManager::TabletManager(std::chrono::milliseconds rescan_interval)
    : interval_(rescan_interval), thread_([this] { run(); }) {}

TabletManager::~TabletManager() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  const std::lock_guard lock(mutex_);
  readers_.clear();
}

namespace {

ConnectedTablet connected_tablet(const TabletReader& reader) {
  const HidDeviceInfo& device = reader.tablet().device;
  std::string name = device.manufacturer;
  if (!device.product.empty()) name += (name.empty() ? "" : " ") + device.product;
  return {device.path, name.empty() ? device.path : name, reader.area()};
}

}  // namespace

std::vector<std::string> TabletManager::connected() const {
  const std::lock_guard lock(mutex_);
  std::vector<std::string> paths;
  for (const auto& reading : readers_) {
    if (reading.reader->running()) paths.push_back(reading.reader->tablet().device.path);
  }
  return paths;
}

std::vector<ConnectedTablet> TabletManager::tablets() const {
  const std::lock_guard lock(mutex_);
  std::vector<ConnectedTablet> list;
  for (const auto& reading : readers_) {
    if (reading.reader->running()) list.push_back(connected_tablet(*reading.reader));
  }
  return list;
}

std::vector<TabletSamples> TabletManager::poll_tablets() {
  const std::lock_guard lock(mutex_);
  std::vector<TabletSamples> polled;
  for (const auto& reading : readers_) {
    std::vector<paintcore::PenSample> samples = reading.queue->drain();
    if (!samples.empty()) polled.push_back({connected_tablet(*reading.reader), std::move(samples)});
  }
  return polled;
}

std::vector<paintcore::PenSample> TabletManager::poll() {
  std::vector<paintcore::PenSample> all;
  for (TabletSamples& tablet : poll_tablets()) {
    all.insert(all.end(), tablet.samples.begin(), tablet.samples.end());
  }
  // Several tablets at once: interleave them by time (each one's order is kept).
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
  return all;
}

void TabletManager::rescan() {
  const std::vector<PenTabletInfo> tablets = find_pen_tablets();
  const std::lock_guard lock(mutex_);
  // Drop readers whose tablet went away (their thread has stopped).
  std::erase_if(readers_, [](const Reading& reading) { return !reading.reader->running(); });
  for (const PenTabletInfo& tablet : tablets) {
    if (!tablet.unsupported_reason.empty() || !tablet.readable) continue;
    const bool reading = std::any_of(readers_.begin(), readers_.end(), [&](const Reading& r) {
      return r.reader->tablet().device.path == tablet.device.path;
    });
    if (reading) continue;
    try {
      Reading fresh;
      fresh.queue = std::make_unique<SampleQueue>();
      fresh.reader = std::make_unique<TabletReader>(tablet, *fresh.queue, origin_);
      readers_.push_back(std::move(fresh));
    } catch (const std::exception&) {
      // A descriptor that changed under us: try again at the next scan.
    }
  }
}

void TabletManager::run() {
  while (!stop_) {
    rescan();
    // Sleep in short steps so that destruction is prompt.
    const auto until = std::chrono::steady_clock::now() + interval_;
    while (!stop_ && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
}

}  // namespace impasto::input::hid
