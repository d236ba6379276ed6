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
#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>

#ifdef IMPASTO_HAVE_HIDAPI
#include <hidapi/hidapi.h>
#endif

namespace impasto::input::hid {

namespace {

// Tablet makers whose vendor-defined collections are worth listing as unsupported pens.
constexpr std::uint16_t kTabletVendors[] = {0x056A /* Wacom */, 0x256C /* Huion */,
                                            0x28BD /* XP-Pen */, 0x5543 /* UC-Logic */,
                                            0x2FEB /* Veikk */};

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

std::vector<std::uint8_t> read_usb_string_descriptor(const std::string& hidraw_path,
                                                     std::uint8_t index) {
  // /sys/class/hidraw/hidrawN/device is the HID device under the USB interface, whose parent
  // is the USB device with its bus and device numbers.
  const std::string node = std::filesystem::path(hidraw_path).filename().string();
  std::error_code error;
  const std::filesystem::path hid_dir = std::filesystem::canonical(
      std::filesystem::path("/sys/class/hidraw") / node / "device", error);
  if (error) throw std::runtime_error(hidraw_path + ": no sysfs entry (" + error.message() + ")");
  const std::filesystem::path usb_dir = hid_dir.parent_path().parent_path();
  int bus = 0, dev = 0;
  std::ifstream(usb_dir / "busnum") >> bus;
  std::ifstream(usb_dir / "devnum") >> dev;
  if (bus <= 0 || dev <= 0) throw std::runtime_error(hidraw_path + ": not a USB device");
  char usbfs[64];
  std::snprintf(usbfs, sizeof usbfs, "/dev/bus/usb/%03d/%03d", bus, dev);
  const int fd = ::open(usbfs, O_RDWR | O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(std::string(usbfs) + ": cannot open (" + std::strerror(errno) + ")");
  }
  std::uint8_t buffer[255] = {};
  usbdevfs_ctrltransfer transfer{};
  transfer.bRequestType = 0x80;  // device to host, standard, device
  transfer.bRequest = 0x06;      // GET_DESCRIPTOR
  transfer.wValue = static_cast<std::uint16_t>(0x0300 | index);
  transfer.wIndex = 0x0409;  // US English, as the vendors' drivers ask
  transfer.wLength = sizeof buffer;
  transfer.timeout = 1000;
  transfer.data = buffer;
  const int n = ::ioctl(fd, USBDEVFS_CONTROL, &transfer);
  const int saved = errno;
  ::close(fd);
  if (n < 2) {
    throw std::runtime_error(std::string(usbfs) + ": string " + std::to_string(index) +
                             " not answered (" + std::strerror(n < 0 ? saved : EIO) + ")");
  }
  return {buffer, buffer + std::min<int>(n, buffer[0] >= 2 ? buffer[0] : n)};
}

InitExchange uclogic_handshake(const std::string& hidraw_path, std::string* error) {
  InitExchange init;
  std::string first_error;
  const auto read = [&](std::uint8_t index) -> const std::vector<std::uint8_t>* {
    try {
      init.strings.push_back({index, read_usb_string_descriptor(hidraw_path, index)});
      return &init.strings.back().bytes;
    } catch (const std::runtime_error& e) {
      init.unanswered.push_back(index);
      if (first_error.empty()) first_error = e.what();
      return nullptr;
    }
  };
  // As hid-uclogic does: the firmware name, then v2 parameters (0xC8); only a tablet without
  // them is asked for v1 (0x64), which would switch it to the v1 reports.
  read(0xC9);
  const auto* v2 = read(kUcLogicParamsV2);
  if (v2 == nullptr || !parse_uclogic_params_v2(*v2)) read(kUcLogicParamsV1);
  read(0x79);  // the model's name on older tablets
  if (error != nullptr) *error = init.strings.empty() ? first_error : "";
  return init;
}

HidSystem this_machine(bool handshake) {
  HidSystem system;
  system.enumerate = enumerate_hid_devices;
  system.read_descriptor = read_report_descriptor;
  system.readable = [](const std::string& path) { return ::access(path.c_str(), R_OK) == 0; };
  if (handshake) {
    system.handshake = [](const HidDeviceInfo& device) { return uclogic_handshake(device.path); };
  }
  return system;
}

std::vector<PenTabletInfo> find_pen_tablets(const HidSystem& system) {
  const std::vector<TabletModel>& models =
      system.models != nullptr ? *system.models : default_tablet_models();
  std::vector<PenTabletInfo> tablets;
  for (const HidDeviceInfo& device : system.enumerate()) {
    PenTabletInfo info;
    info.device = device;
    info.readable = system.readable ? system.readable(device.path) : false;
    try {
      info.descriptor = system.read_descriptor(device.path);
    } catch (const std::runtime_error& e) {
      // Only a tablet maker's device is worth reporting without its descriptor.
      if (!is_tablet_vendor(device.vendor_id)) continue;
      info.unsupported_reason = e.what();
      tablets.push_back(std::move(info));
      continue;
    }
    const bool known_model =
        !find_tablet_models(models, device.vendor_id, device.product_id).empty() ||
        find_graphire_tablet(device.vendor_id, device.product_id).has_value();
    bool pen = false;
    bool vendor_application = false;
    try {
      const ReportDescriptor d = parse_report_descriptor(info.descriptor, device.path);
      pen = declares_pen(d) || unsupported_reason(d).empty();
      vendor_application = has_vendor_application(d);
    } catch (const InputFormatError&) {
    }
    if (!pen && !(is_tablet_vendor(device.vendor_id) && (vendor_application || known_model))) {
      continue;
    }
    if (system.handshake && is_uclogic_vendor(device.vendor_id)) {
      info.init = system.handshake(device);
    }
    try {
      const TabletDecoder decoder(info.descriptor, device.vendor_id, device.product_id, info.init,
                                  models);
      info.summary = decoder.summary();
    } catch (const UnsupportedTablet& e) {
      std::string reason = e.what();
      const std::string prefix = "unsupported tablet: ";
      if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
      if (is_uclogic_vendor(device.vendor_id) && info.init.empty()) {
        reason += "; its UC-Logic handshake was not made (impasto hid list --handshake)";
      }
      info.unsupported_reason = reason;
    } catch (const InputFormatError& e) {
      info.unsupported_reason = std::string("malformed descriptor: ") + e.what();
    }
    tablets.push_back(std::move(info));
  }
  return tablets;
}

std::vector<PenTabletInfo> find_pen_tablets() {
  return find_pen_tablets(this_machine());
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

void HidDevice::write(const std::vector<std::uint8_t>& report) {
#ifdef IMPASTO_HAVE_HIDAPI
  const int n = hid_write(static_cast<hid_device*>(handle_), report.data(), report.size());
  if (n < 0) {
    throw std::runtime_error(
        path_ + ": write failed: " + narrow(hid_error(static_cast<hid_device*>(handle_))));
  }
#else
  (void)report;
  throw std::runtime_error(path_ + ": this impasto was built without hidapi");
#endif
}

InitExchange initialise_tablet(const HidDeviceInfo& device, HidDevice& open_device,
                               const std::vector<TabletModel>& models, std::string* error) {
  InitExchange init;
  std::string problem;
  const std::vector<TabletModel> rows =
      find_tablet_models(models, device.vendor_id, device.product_id);
  if (is_uclogic_vendor(device.vendor_id) &&
      (rows.empty() || rows.front().protocol == ModelProtocol::kUcLogic)) {
    init = uclogic_handshake(device.path, &problem);
  } else if (!rows.empty()) {
    for (const InitStep& step : rows.front().init) {
      try {
        if (step.kind == InitStep::Kind::kSendOutput) {
          open_device.write(step.report);
          init.output_reports.push_back(step.report);
        } else {
          init.strings.push_back(
              {step.string_index, read_usb_string_descriptor(device.path, step.string_index)});
        }
      } catch (const std::runtime_error& e) {
        if (problem.empty()) problem = e.what();
      }
    }
  }
  if (error != nullptr) *error = problem;
  return init;
}

TabletReader::TabletReader(PenTabletInfo tablet, SampleQueue& queue,
                           std::chrono::steady_clock::time_point origin)
    : tablet_(std::move(tablet)),
      decoder_(tablet_.descriptor, tablet_.device.vendor_id, tablet_.device.product_id,
               tablet_.init, default_tablet_models()),
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
    // A tablet whose pen needs its vendor's initialisation gets it here; the decoder then
    // follows the tablet's answer. Not when the descriptor already describes the vendor's
    // report (a kernel driver such as hid-uclogic has made the handshake and rewrites the
    // reports: doing it again would read them twice over).
    TabletDecoder decoder = decoder_;
    if (const auto& vendor = decoder_.vendor_format();
        vendor && tablet_.init.empty() && !decoder_.describes_report(vendor->report_id())) {
      const InitExchange init =
          initialise_tablet(tablet_.device, device, default_tablet_models(), nullptr);
      if (!init.empty()) {
        try {
          decoder = TabletDecoder(tablet_.descriptor, tablet_.device.vendor_id,
                                  tablet_.device.product_id, init, default_tablet_models());
        } catch (const std::exception&) {
          // keep the model table's decoder
        }
      }
    }
    while (!stop_) {
      const std::vector<std::uint8_t> report = device.read(kReadTimeoutMs);
      if (report.empty()) continue;
      const double time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - origin_).count();
      try {
        if (auto sample = decoder.decode(report, time_s)) queue_.push(*sample);
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
