#pragma once
// One decoder for any tablet Impasto can read: standard HID pen reports through the report
// descriptor (in any collection, or in Wacom's vendor page), a vendor protocol chosen by the
// model table (hid_models.hpp) and the tablet's handshake (UC-Logic), or Wacom's Graphire.
#include <impasto/input/hid_init_exchange.hpp>
#include <impasto/input/hid_models.hpp>
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/hid_vendor.hpp>
#include <impasto/input/hid_vendor_pen.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace impasto::input::hid {

// What `impasto hid list` shows about a tablet.
struct TabletSummary {
  std::string vendor;    // "Huion", "XP-Pen / Ugee", ... from the vendor id
  std::string model;     // the model table's name, else empty
  std::string protocol;  // "HID descriptor", "UC-Logic v1 (handshake)", ...
  double width_mm = 0.0;
  double height_mm = 0.0;
  bool area_known = false;  // stated by the descriptor, the model table or the handshake
  std::uint32_t pressure_levels = 0;
  bool tilt = false;
};

// The company behind a USB vendor id, or "" when Impasto does not know it.
std::string tablet_vendor_name(std::uint16_t vendor_id);

class TabletDecoder {
 public:
  // Throws UnsupportedTablet (with the reason) when no way applies, and InputFormatError
  // when the descriptor is malformed and no vendor protocol applies.
  TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                std::uint16_t product_id, DecoderOptions options = {});
  // `init` is what the tablet answered to its handshake (empty if none was made); `models`
  // the model table.
  TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                std::uint16_t product_id, const InitExchange& init,
                const std::vector<TabletModel>& models, DecoderOptions options = {});

  // A pen sample in tablet mm, or nullopt for reports that carry no pen state. Throws
  // InputFormatError, naming `source`, for a malformed pen report.
  std::optional<paintcore::PenSample> decode(std::span<const std::uint8_t> report, double time_s,
                                             const std::string& source = "report") const;
  TabletArea area() const;
  // What `impasto hid list` shows about the pen, one line.
  std::string describe() const;
  TabletSummary summary() const { return summary_; }
  const std::optional<VendorPenFormat>& vendor_format() const { return vendor_; }
  // Whether the descriptor describes input report `report_id` as a pen report.
  bool describes_report(std::uint8_t report_id) const;

 private:
  std::optional<GraphireTablet> graphire_;
  std::optional<VendorPenFormat> vendor_;
  bool vendor_first_ = false;  // the handshake was made: vendor reports win over the descriptor
  std::optional<PenDecoder> pen_;
  TabletSummary summary_;
};

}  // namespace impasto::input::hid
