// impasto hid ...: pen tablets through USB HID. List the tablets on this machine, describe a
// report descriptor, decode recorded reports to a table, record a live tablet.
#include <impasto/files/input_file.hpp>
#include <impasto/input/hid_capture.hpp>
#include <impasto/input/hid_describe.hpp>
#include <impasto/input/hid_device.hpp>
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_tablet.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "command.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::hid_cmd {

namespace {

namespace hid = impasto::input::hid;

// The tablets as JSON: what a script needs to pick one (its node, ids, model, area, levels).
nlohmann::json tablets_json(const std::vector<hid::PenTabletInfo>& tablets) {
  nlohmann::json list = nlohmann::json::array();
  for (const hid::PenTabletInfo& t : tablets) {
    char id[16];
    std::snprintf(id, sizeof id, "%04x:%04x", t.device.vendor_id, t.device.product_id);
    nlohmann::json row{{"path", t.device.path},
                       {"id", id},
                       {"manufacturer", t.device.manufacturer},
                       {"product", t.device.product},
                       {"interface", t.device.interface_number},
                       {"readable", t.readable},
                       {"supported", t.unsupported_reason.empty()},
                       {"unsupported_reason", t.unsupported_reason}};
    if (t.summary) {
      row["vendor"] = t.summary->vendor;
      row["model"] = t.summary->model;
      row["protocol"] = t.summary->protocol;
      if (t.summary->area_known) row["area_mm"] = {t.summary->width_mm, t.summary->height_mm};
      row["pressure_levels"] = t.summary->pressure_levels;
      row["tilt"] = t.summary->tilt;
    }
    list.push_back(row);
  }
  return list;
}

void list_tablets(bool handshake, bool json) {
  if (!hid::hid_available()) {
    throw std::runtime_error("this impasto was built without hidapi: no tablet access");
  }
  std::string models_error;
  (void)hid::default_tablet_models(&models_error);
  if (!models_error.empty())
    std::cerr << "warning: no tablet model table: " << models_error << "\n";
  const auto tablets = hid::find_pen_tablets(hid::this_machine(handshake));
  if (json) {
    std::cout << tablets_json(tablets).dump(2) << "\n";
    return;
  }
  if (tablets.empty()) {
    const std::size_t devices = hid::enumerate_hid_devices().size();
    std::cout << "No pen tablets found: " << devices << " HID device(s) seen"
              << (devices == 0 ? " (no /dev/hidraw nodes, or hidapi cannot list them)" : "")
              << ", none declares a pen digitizer.\n";
    return;
  }
  std::cout << hid::describe_tablet_list(tablets);
  const bool any_unreadable = std::any_of(tablets.begin(), tablets.end(),
                                          [](const hid::PenTabletInfo& t) { return !t.readable; });
  if (any_unreadable) {
    std::cout << "Install packaging/udev/70-impasto-tablets.rules in /etc/udev/rules.d, then "
                 "replug the tablet (or log in again).\n";
  }
}

// What a command knows of the tablet besides its descriptor: its ids (--id, or a capture's
// I: line) and its handshake (--strings: a probe file or a capture with S: lines).
struct TabletContext {
  std::uint16_t vendor = 0;
  std::uint16_t product = 0;
  hid::InitExchange init;
};

std::pair<std::uint16_t, std::uint16_t> parse_id(const std::string& text) {
  unsigned vendor = 0, product = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%x:%x%c", &vendor, &product, &extra) != 2 || vendor > 0xFFFF ||
      product > 0xFFFF) {
    throw std::runtime_error("--id: expected VID:PID in hex (e.g. 256c:006e), got '" + text + "'");
  }
  return {static_cast<std::uint16_t>(vendor), static_cast<std::uint16_t>(product)};
}

hid::InitExchange read_strings(const std::string& path) {
  const std::string text = files::read_whole_file(path, "HID capture", files::kMaxRecordingBytes);
  if (hid::detect_capture_format(text, false) == hid::CaptureFormat::kHidRecorder) {
    std::istringstream capture(text);
    return hid::parse_hid_recording(capture, path).init;
  }
  return hid::parse_string_probe(text, path);
}

// A capture names its device and carries its handshake; --id and --strings override.
TabletContext tablet_context(const std::string& capture_path, const std::string& id,
                             const std::string& strings,
                             const std::vector<std::uint8_t>& descriptor) {
  TabletContext context;
  try {
    const hid::HidRecording capture = hid::read_hid_recording(capture_path);
    if (capture.descriptor == descriptor) {
      context.vendor = capture.vendor_id;
      context.product = capture.product_id;
      context.init = capture.init;
    }
  } catch (const std::runtime_error&) {
    // not a hid-recorder capture: the descriptor alone decides
  }
  if (!id.empty()) std::tie(context.vendor, context.product) = parse_id(id);
  if (!strings.empty()) context.init = read_strings(strings);
  return context;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
}

struct DescribeOptions {
  std::string path, id, strings;
  int interface = -1;
};

void describe(const DescribeOptions& o) {
  const hid::DescriptorFile file = hid::read_descriptor_file(
      o.path, o.interface >= 0 ? std::optional<int>(o.interface) : std::nullopt);
  print_warnings(file.warnings);
  const hid::ReportDescriptor descriptor = hid::parse_report_descriptor(file.bytes, o.path);
  std::cout << o.path << ": " << hid::capture_format_name(file.format);
  if (file.interface >= 0) std::cout << " (interface " << file.interface << ")";
  std::cout << ", " << file.bytes.size() << " bytes, " << hid::describe_reports(descriptor);
  const TabletContext c = tablet_context(o.path, o.id, o.strings, file.bytes);
  try {
    const hid::TabletDecoder decoder(file.bytes, c.vendor, c.product, c.init,
                                     hid::default_tablet_models());
    std::cout << "pen: " << decoder.describe();
  } catch (const hid::UnsupportedTablet& e) {
    std::cout << "pen: " << e.what() << "\n";
  }
}

struct DecodeOptions {
  std::string descriptor, reports, id, strings;
  int interface = -1;
};

void decode(const DecodeOptions& o) {
  const std::optional<int> interface =
      o.interface >= 0 ? std::optional<int>(o.interface) : std::nullopt;
  const hid::DescriptorFile descriptor = hid::read_descriptor_file(o.descriptor, interface);
  const hid::ReportFile reports = hid::read_report_file(o.reports, interface);
  print_warnings(descriptor.warnings);
  print_warnings(reports.warnings);
  std::cerr << o.descriptor << ": " << hid::capture_format_name(descriptor.format) << "; "
            << o.reports << ": " << hid::capture_format_name(reports.format) << ", "
            << reports.reports.size() << " reports\n";
  const TabletContext c = tablet_context(o.reports, o.id, o.strings, descriptor.bytes);
  const hid::TabletDecoder decoder(descriptor.bytes, c.vendor, c.product, c.init,
                                   hid::default_tablet_models());
  std::cerr << "pen: " << decoder.describe().substr(0, decoder.describe().find('\n')) << "\n";
  std::printf("time\tx_mm\ty_mm\tpressure\ttilt_x\ttilt_y\ttip\tin_range\tbuttons\n");
  std::size_t rows = 0;
  for (std::size_t i = 0; i < reports.reports.size(); ++i) {
    const hid::RecordedReport& r = reports.reports[i];
    const auto s =
        decoder.decode(r.bytes, r.time_s, o.reports + ": report " + std::to_string(i + 1));
    if (!s) continue;
    ++rows;
    std::printf("%.6f\t%.4f\t%.4f\t%.5f\t%.2f\t%.2f\t%d\t%d\t%u\n", s->time_s, s->x_mm, s->y_mm,
                static_cast<double>(s->pressure), static_cast<double>(s->tilt_x_deg),
                static_cast<double>(s->tilt_y_deg), s->tip_down() ? 1 : 0,
                (s->buttons & paintcore::kPenInRange) ? 1 : 0, s->buttons);
  }
  if (rows == 0) {
    std::cerr << o.reports << ": none of its " << reports.reports.size()
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
  // The tablet's initialisation, stored in the capture so that it replays through the same
  // decoder (hid-uclogic-style handshake, or the model table's output reports).
  hid::HidDeviceInfo info{device_path, capture.vendor_id, capture.product_id, "", "", -1};
  std::string init_problem;
  capture.init = hid::initialise_tablet(info, device, hid::default_tablet_models(), &init_problem);
  if (!init_problem.empty()) std::cerr << "initialisation: " << init_problem << "\n";
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

      static bool list_handshake = false;
      auto* list_cmd = group->add_subcommand("list", "List pen tablets and their capabilities");
      list_cmd->add_flag("--handshake", list_handshake,
                         "ask Huion/Gaomon/XP-Pen/Ugee tablets for their parameters (this "
                         "switches them to their full-resolution reports)");
      static bool list_json = false;
      add_json_flag(*list_cmd, list_json,
                    "each tablet's node, USB id, model, area, pressure levels and whether "
                    "Impasto can read it");
      list_cmd->callback([] { list_tablets(list_handshake, list_json); });

      const auto tablet_options = [](CLI::App* cmd, std::string& id, std::string& strings,
                                     int& interface) {
        cmd->add_option("--id", id, "the tablet's USB VID:PID in hex (usbhid-dump files lack it)");
        cmd->add_option("--strings", strings,
                        "its string descriptors: a probe file (S lines) or a capture (S: lines)");
        cmd->add_option("--interface", interface, "usbhid-dump: the interface to read");
      };
      static DescribeOptions describe_options;
      auto* describe_cmd = group->add_subcommand("describe", "Show the fields of each report");
      describe_cmd
          ->add_option("DESCRIPTOR", describe_options.path,
                       "report descriptor: raw .bin, hex text, usbhid-dump or hid-recorder")
          ->required();
      tablet_options(describe_cmd, describe_options.id, describe_options.strings,
                     describe_options.interface);
      describe_cmd->callback([] { describe(describe_options); });

      static DecodeOptions decode_options;
      auto* decode_cmd = group->add_subcommand("decode", "Decode pen reports to TSV on stdout");
      decode_cmd->add_option("--descriptor", decode_options.descriptor, "report descriptor file")
          ->required();
      decode_cmd
          ->add_option("--reports", decode_options.reports,
                       "reports: usbhid-dump or hid-recorder capture, or one hex report a line")
          ->required();
      tablet_options(decode_cmd, decode_options.id, decode_options.strings,
                     decode_options.interface);
      decode_cmd->callback([] { decode(decode_options); });

      static std::string record_out;
      static std::string record_device;
      static double record_seconds = 0.0;
      auto* record_cmd =
          group->add_subcommand("record", "Capture a tablet's reports in hid-recorder format");
      add_out_option(*record_cmd, record_out, "the capture, hid-recorder format")->required();
      record_cmd->add_option("--device", record_device, "hidraw node (default: first pen tablet)");
      record_cmd
          ->add_option("--seconds", record_seconds, "stop after this many seconds (0: Ctrl+C)")
          ->check(CLI::NonNegativeNumber);
      record_cmd->callback([] { record(record_out, record_device, record_seconds); });
    }};

}  // namespace

}  // namespace impasto::app::hid_cmd
