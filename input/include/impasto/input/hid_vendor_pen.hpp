#pragma once
// Pen reports that no descriptor describes: the vendor protocols of Huion/Gaomon and older
// XP-Pen/Ugee (UC-Logic), current XP-Pen/Ugee, Veikk, and Wacom's Intuos V2. Their extents and
// pressure levels come from the UC-Logic handshake (string descriptors 0x64 / 0xC8) or from the
// model data file (hid_models.hpp). Layouts as the Linux hid-uclogic driver and OpenTabletDriver
// read them (docs/hid.md).
#include <impasto/input/hid_init_exchange.hpp>
#include <impasto/paintcore/pen_sample.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace impasto::input::hid {

enum class VendorProtocol {
  kUcLogicV1,      // report 7, 16-bit x/y, in-range bit inverted, tilt bytes on some models
  kUcLogicV2,      // report 8, 24-bit x/y split over the report, tilt in degrees
  kXpPen,          // report 2, 16-bit x/y (24-bit in 12-byte reports), tilt, eraser
  kVeikkV1,        // report 9, the pen state after a 0x41 byte
  kWacomIntuosV2,  // report 16, 24-bit x/y, tilt, eraser (what Wacom's 0xFF0D page describes)
};
const char* vendor_protocol_name(VendorProtocol protocol);

// The full-resolution extents, pressure levels and resolution a UC-Logic tablet answers in
// its parameter string descriptor. Reading that descriptor also switches the tablet from
// its default (mouse-compatible) reports to its vendor pen reports.
struct UcLogicParams {
  int version = 1;  // 1: string 0x64; 2: string 0xC8 (24-bit extents, tilt)
  std::uint32_t max_x = 0;
  std::uint32_t max_y = 0;
  std::uint32_t max_pressure = 0;
  std::uint32_t lines_per_inch = 0;  // 0 when the tablet does not say
  double width_mm() const;           // 0 without a resolution
  double height_mm() const;
};

inline constexpr std::uint8_t kUcLogicParamsV1 = 0x64;
inline constexpr std::uint8_t kUcLogicParamsV2 = 0xC8;

// Parses a raw parameter string descriptor (bLength, 3, payload). nullopt when it is too
// short, all text (some tablets answer every unknown index with their name) or has zero
// extents.
std::optional<UcLogicParams> parse_uclogic_params_v1(std::span<const std::uint8_t> descriptor);
std::optional<UcLogicParams> parse_uclogic_params_v2(std::span<const std::uint8_t> descriptor);
// The handshake's answer: v2 (0xC8) when the tablet gave one, else v1 (0x64).
std::optional<UcLogicParams> uclogic_params(const InitExchange& init);

// How to scale one vendor protocol's reports.
struct VendorPenFormat {
  VendorProtocol protocol = VendorProtocol::kUcLogicV1;
  std::uint32_t max_x = 0;
  std::uint32_t max_y = 0;
  std::uint32_t max_pressure = 0;
  double width_mm = 0.0;
  double height_mm = 0.0;
  bool tilt = false;

  std::uint8_t report_id() const;
};

// A UC-Logic format from the handshake's parameters.
VendorPenFormat uclogic_format(const UcLogicParams& params);

// One report in tablet mm: x = raw / max_x * width (clamped), pressure = raw / max_pressure,
// tilt in degrees. nullopt for reports of other IDs, frame (pad button) reports and reports
// too short for the protocol.
std::optional<paintcore::PenSample> decode_vendor_pen_report(const VendorPenFormat& format,
                                                             std::span<const std::uint8_t> report,
                                                             double time_s);

}  // namespace impasto::input::hid
