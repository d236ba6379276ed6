// impasto hid ...: pen tablets through USB HID. List the tablets on this machine, describe a
// report descriptor, decode recorded reports to a table, record a live tablet.
#include <impasto/input/hid_describe.hpp>
#include <impasto/input/hid_device.hpp>
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_tablet.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "command.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::hid_cmd {

namespace {

namespace hid = impasto::input::hid;

std::string hex4(unsigned value) {
  char text[8];
  std::snprintf(text, sizeof text, "%04x", value & 0xFFFFu);
  return text;
}

void list_tablets() {
  if (!hid::hid_available()) {
    throw std::runtime_error("this impasto was built without hidapi: no tablet access");
  }
  const auto tablets = hid::find_pen_tablets();
  if (tablets.empty()) {
    const std::size_t devices = hid::enumerate_hid_devices().size();
    std::cout << "No pen tablets found: " << devices << " HID device(s) seen"
              << (devices == 0 ? " (no /dev/hidraw nodes, or hidapi cannot list them)" : "")
              << ", none declares a pen digitizer.\n";
    return;
  }
  bool any_unreadable = false;
  for (const hid::PenTabletInfo& t : tablets) {
    any_unreadable = any_unreadable || !t.readable;
    std::cout << t.device.path << "  " << hex4(t.device.vendor_id) << ":"
              << hex4(t.device.product_id) << "  " << t.device.manufacturer << " "
              << t.device.product << "\n";
    if (!t.unsupported_reason.empty()) {
      std::cout << "  unsupported: " << t.unsupported_reason << "\n";
      continue;
    }
    const hid::TabletDecoder decoder(t.descriptor, t.device.vendor_id, t.device.product_id);
    std::cout << "  " << decoder.describe();
    if (!t.readable) std::cout << "  no permission to read " << t.device.path << "\n";
  }
  if (any_unreadable) {
    std::cout << "Install packaging/udev/70-impasto-tablets.rules in /etc/udev/rules.d, then "
                 "replug the tablet (or log in again).\n";
  }
}

void describe(const std::string& path) {
  const auto bytes = hid::load_descriptor_bytes(path);
  const hid::ReportDescriptor descriptor = hid::parse_report_descriptor(bytes, path);
  std::cout << path << ": " << bytes.size() << " bytes, " << hid::describe_reports(descriptor);
  const std::string reason = hid::unsupported_reason(descriptor);
  std::optional<hid::GraphireTablet> vendor_protocol;
  try {  // a capture names its device, which may speak a known vendor protocol
    const hid::HidRecording capture = hid::read_hid_recording(path);
    vendor_protocol = hid::find_graphire_tablet(capture.vendor_id, capture.product_id);
  } catch (const std::runtime_error&) {
  }
  if (vendor_protocol) {
    std::cout << "pen: "
              << hid::TabletDecoder(bytes, 0x056A, vendor_protocol->product_id).describe();
  } else if (reason.empty()) {
    std::cout << hid::describe_pen(hid::PenDecoder(descriptor));
  } else {
    std::cout << "pen: unsupported: " << reason << "\n";
  }
}

void decode(const std::string& descriptor_path, const std::string& reports_path) {
  const auto descriptor = hid::load_descriptor_bytes(descriptor_path);
  const auto reports = hid::load_reports(reports_path);
  // A capture names its device: when the descriptor is the capture's own, a tablet with a
  // known vendor protocol is decoded by that protocol.
  std::uint16_t vendor = 0;
  std::uint16_t product = 0;
  try {
    const hid::HidRecording capture = hid::read_hid_recording(reports_path);
    if (capture.descriptor == descriptor) {
      vendor = capture.vendor_id;
      product = capture.product_id;
    }
  } catch (const std::runtime_error&) {
    // plain hex lines: the descriptor alone decides
  }
  const hid::TabletDecoder decoder(descriptor, vendor, product);
  std::printf("time\tx_mm\ty_mm\tpressure\ttilt_x\ttilt_y\ttip\tin_range\tbuttons\n");
  std::size_t rows = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto s = decoder.decode(reports[i].bytes, reports[i].time_s,
                                  reports_path + ": report " + std::to_string(i + 1));
    if (!s) continue;
    ++rows;
    std::printf("%.6f\t%.4f\t%.4f\t%.5f\t%.2f\t%.2f\t%d\t%d\t%u\n", s->time_s, s->x_mm, s->y_mm,
                static_cast<double>(s->pressure), static_cast<double>(s->tilt_x_deg),
                static_cast<double>(s->tilt_y_deg), s->tip_down() ? 1 : 0,
                (s->buttons & paintcore::kPenInRange) ? 1 : 0, s->buttons);
  }
  if (rows == 0) {
    std::cerr << reports_path << ": none of its " << reports.size()
              << " reports is a pen report of this descriptor\n";
  }
}

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) {
  g_interrupted = true;
}

void record(const std::string& out_path, std::string device_path, double seconds) {
  if (!hid::hid_available()) throw std::runtime_error("this impasto was built without hidapi");
  hid::HidRecording capture;
  if (device_path.empty()) {
    for (const hid::PenTabletInfo& t : hid::find_pen_tablets()) {
      if (t.readable) {
        device_path = t.device.path;
        break;
      }
    }
    if (device_path.empty()) {
      throw std::runtime_error("no readable pen tablet (see `impasto hid list`)");
    }
  }
  for (const hid::HidDeviceInfo& d : hid::enumerate_hid_devices()) {
    if (d.path != device_path) continue;
    capture.vendor_id = d.vendor_id;
    capture.product_id = d.product_id;
    capture.name = d.manufacturer + " " + d.product;
  }
  capture.bus = 3;  // USB
  capture.phys = device_path;
  capture.descriptor = hid::read_report_descriptor(device_path);
  hid::HidDevice device(device_path);
  std::ofstream out(out_path, std::ios::trunc);
  if (!out) throw std::runtime_error(out_path + ": cannot create the file");
  hid::write_hid_recording(out, capture);  // header now; events follow as they come
  out.flush();
  std::signal(SIGINT, on_interrupt);
  std::cerr << "recording " << device_path << " to " << out_path << " (Ctrl+C to stop)\n";
  const auto start = std::chrono::steady_clock::now();
  std::size_t count = 0;
  while (!g_interrupted) {
    const double now =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.0 && now >= seconds) break;
    std::vector<std::uint8_t> report = device.read(50);
    if (report.empty()) continue;
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << hid::recorder_event_line({t, std::move(report)}) << "\n" << std::flush;
    ++count;
  }
  std::signal(SIGINT, SIG_DFL);
  std::cerr << count << " reports recorded\n";
}

const CommandRegistrar kRegistrar{
    "hid", [](CLI::App& root) {
      CLI::App* group = command_group(root, "hid", "Pen tablets through USB HID");
      group->require_subcommand(1);

      auto* list_cmd = group->add_subcommand("list", "List pen tablets and their capabilities");
      list_cmd->callback(list_tablets);

      static std::string descriptor_path;
      auto* describe_cmd = group->add_subcommand("describe", "Show the fields of each report");
      describe_cmd
          ->add_option("DESCRIPTOR", descriptor_path,
                       "report descriptor: raw .bin, hex text, or a hid-recorder capture")
          ->required();
      describe_cmd->callback([] { describe(descriptor_path); });

      static std::string decode_descriptor;
      static std::string decode_reports;
      auto* decode_cmd = group->add_subcommand("decode", "Decode pen reports to TSV on stdout");
      decode_cmd->add_option("--descriptor", decode_descriptor, "report descriptor file")
          ->required();
      decode_cmd
          ->add_option("--reports", decode_reports,
                       "reports: a hid-recorder capture (E: lines) or one hex report a line")
          ->required();
      decode_cmd->callback([] { decode(decode_descriptor, decode_reports); });

      static std::string record_out;
      static std::string record_device;
      static double record_seconds = 0.0;
      auto* record_cmd =
          group->add_subcommand("record", "Capture a tablet's reports in hid-recorder format");
      record_cmd->add_option("--out", record_out, "output file")->required();
      record_cmd->add_option("--device", record_device, "hidraw node (default: first pen tablet)");
      record_cmd
          ->add_option("--seconds", record_seconds, "stop after this many seconds (0: Ctrl+C)")
          ->check(CLI::NonNegativeNumber);
      record_cmd->callback([] { record(record_out, record_device, record_seconds); });
    }};

}  // namespace

}  // namespace impasto::app::hid_cmd
