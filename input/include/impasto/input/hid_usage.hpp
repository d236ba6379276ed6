#pragma once
// HID usages: a 16-bit usage page and a 16-bit usage id in one 32-bit value (the "extended
// usage" of HID 1.11, section 6.2.2.8), and the ones a pen tablet uses.
#include <cstdint>
#include <string>

namespace impasto::input::hid {

using Usage = std::uint32_t;

constexpr Usage make_usage(std::uint16_t page, std::uint16_t id) {
  return (static_cast<Usage>(page) << 16) | id;
}
constexpr std::uint16_t usage_page(Usage usage) {
  return static_cast<std::uint16_t>(usage >> 16);
}
constexpr std::uint16_t usage_id(Usage usage) {
  return static_cast<std::uint16_t>(usage);
}

namespace page {
inline constexpr std::uint16_t kGenericDesktop = 0x01;
inline constexpr std::uint16_t kButton = 0x09;
inline constexpr std::uint16_t kDigitizer = 0x0D;
inline constexpr std::uint16_t kVendorFirst = 0xFF00;  // 0xFF00..0xFFFF are vendor-defined
}  // namespace page

namespace usage {
inline constexpr Usage kX = make_usage(page::kGenericDesktop, 0x30);
inline constexpr Usage kY = make_usage(page::kGenericDesktop, 0x31);
inline constexpr Usage kDigitizer = make_usage(page::kDigitizer, 0x01);
inline constexpr Usage kPen = make_usage(page::kDigitizer, 0x02);
inline constexpr Usage kStylus = make_usage(page::kDigitizer, 0x20);
inline constexpr Usage kTipPressure = make_usage(page::kDigitizer, 0x30);
inline constexpr Usage kInRange = make_usage(page::kDigitizer, 0x32);
inline constexpr Usage kInvert = make_usage(page::kDigitizer, 0x3C);
inline constexpr Usage kXTilt = make_usage(page::kDigitizer, 0x3D);
inline constexpr Usage kYTilt = make_usage(page::kDigitizer, 0x3E);
inline constexpr Usage kTwist = make_usage(page::kDigitizer, 0x41);
inline constexpr Usage kTipSwitch = make_usage(page::kDigitizer, 0x42);
inline constexpr Usage kBarrelSwitch = make_usage(page::kDigitizer, 0x44);
inline constexpr Usage kEraser = make_usage(page::kDigitizer, 0x45);
inline constexpr Usage kSecondaryBarrelSwitch = make_usage(page::kDigitizer, 0x5A);
}  // namespace usage

// A readable name: "X", "Tip Pressure", "Button 2", "Vendor Usage 1", else "0xPPPP:0xIIII".
std::string usage_name(Usage usage);

// The name of a usage page: "Digitizer", "Generic Desktop", "Vendor 0xFF0D", ...
std::string usage_page_name(std::uint16_t page);

}  // namespace impasto::input::hid
