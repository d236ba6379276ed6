// Fuzz target: any bytes as the files tablet owners send (usbhid-dump output, a string
// descriptor probe, the model table), then every report through the vendor protocols and a
// tablet decoder built from the handshake. Nothing may crash; samples stay finite and on the
// tablet.
#include <impasto/input/hid_capture.hpp>
#include <impasto/input/hid_models.hpp>
#include <impasto/input/hid_tablet.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace hid = impasto::input::hid;

namespace {

void check(const impasto::paintcore::PenSample& s, double width, double height) {
  const bool finite = std::isfinite(s.x_mm) && std::isfinite(s.y_mm) && std::isfinite(s.pressure) &&
                      std::isfinite(s.tilt_x_deg) && std::isfinite(s.tilt_y_deg);
  const bool inside = s.x_mm >= 0.0 && s.x_mm <= width + 1e-9 && s.y_mm >= 0.0 &&
                      s.y_mm <= height + 1e-9 && s.pressure >= 0.0f && s.pressure <= 1.0f;
  if (!finite || !inside) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  (void)hid::detect_capture_format(text, false);
  const hid::UsbhidDump dump = hid::parse_usbhid_dump(text, "fuzz");
  hid::InitExchange init;
  try {
    init = hid::parse_string_probe(text, "fuzz");
  } catch (const impasto::input::InputFormatError&) {
  }
  try {
    std::istringstream in(text);
    (void)hid::parse_tablet_models(in, "fuzz");
  } catch (const impasto::input::InputFormatError&) {
  }
  // The records' own bytes as parameter strings, and every protocol over every report.
  for (const hid::UsbhidDumpRecord& r : dump.records) {
    init.strings.push_back({hid::kUcLogicParamsV1, r.bytes});
    init.strings.push_back({hid::kUcLogicParamsV2, r.bytes});
    if (init.strings.size() > 8) break;
  }
  for (const hid::InitExchange& answer : {init}) {
    const auto params = hid::uclogic_params(answer);
    for (hid::VendorProtocol p : {hid::VendorProtocol::kUcLogicV1, hid::VendorProtocol::kUcLogicV2,
                                  hid::VendorProtocol::kXpPen, hid::VendorProtocol::kVeikkV1,
                                  hid::VendorProtocol::kWacomIntuosV2}) {
      hid::VendorPenFormat f = params ? hid::uclogic_format(*params) : hid::VendorPenFormat{};
      f.protocol = p;
      if (!params) f.max_x = 1000, f.max_y = 1000, f.max_pressure = 1023;
      f.width_mm = f.width_mm > 0.0 ? f.width_mm : 100.0;
      f.height_mm = f.height_mm > 0.0 ? f.height_mm : 100.0;
      for (const hid::UsbhidDumpRecord& r : dump.records) {
        std::vector<std::uint8_t> report = r.bytes;
        if (!report.empty()) report[0] = f.report_id();
        if (auto s = hid::decode_vendor_pen_report(f, report, r.time_s)) {
          check(*s, f.width_mm, f.height_mm);
        }
      }
    }
  }
  // A decoder from the first descriptor record and the handshake, over the streams.
  for (const hid::UsbhidDumpRecord& d : dump.records) {
    if (!d.descriptor) continue;
    try {
      const hid::TabletDecoder decoder(d.bytes, 0x256C, 0x006E, init, {});
      for (const hid::UsbhidDumpRecord& r : dump.records) {
        try {
          (void)decoder.decode(r.bytes, r.time_s, "fuzz");
        } catch (const impasto::input::InputFormatError&) {
        }
      }
    } catch (const impasto::input::InputFormatError&) {
    } catch (const hid::UnsupportedTablet&) {
    }
    break;
  }
  return 0;
}
