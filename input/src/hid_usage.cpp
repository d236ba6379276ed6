#include <impasto/input/hid_usage.hpp>

#include <cstdio>

namespace impasto::input::hid {

namespace {

struct NamedUsage {
  Usage usage;
  const char* name;
};

// The usages Impasto meets on pen tablets (HID Usage Tables 1.3, pages 0x01 and 0x0D).
constexpr NamedUsage kNames[] = {
    {make_usage(page::kGenericDesktop, 0x01), "Pointer"},
    {make_usage(page::kGenericDesktop, 0x02), "Mouse"},
    {make_usage(page::kGenericDesktop, 0x06), "Keyboard"},
    {make_usage(page::kGenericDesktop, 0x30), "X"},
    {make_usage(page::kGenericDesktop, 0x31), "Y"},
    {make_usage(page::kGenericDesktop, 0x32), "Z"},
    {make_usage(page::kGenericDesktop, 0x38), "Wheel"},
    {make_usage(page::kGenericDesktop, 0x80), "System Control"},
    {make_usage(page::kDigitizer, 0x01), "Digitizer"},
    {make_usage(page::kDigitizer, 0x02), "Pen"},
    {make_usage(page::kDigitizer, 0x04), "Touch Screen"},
    {make_usage(page::kDigitizer, 0x05), "Touch Pad"},
    {make_usage(page::kDigitizer, 0x20), "Stylus"},
    {make_usage(page::kDigitizer, 0x22), "Finger"},
    {make_usage(page::kDigitizer, 0x30), "Tip Pressure"},
    {make_usage(page::kDigitizer, 0x31), "Barrel Pressure"},
    {make_usage(page::kDigitizer, 0x32), "In Range"},
    {make_usage(page::kDigitizer, 0x33), "Touch"},
    {make_usage(page::kDigitizer, 0x36), "Quality"},
    {make_usage(page::kDigitizer, 0x3C), "Invert"},
    {make_usage(page::kDigitizer, 0x3D), "X Tilt"},
    {make_usage(page::kDigitizer, 0x3E), "Y Tilt"},
    {make_usage(page::kDigitizer, 0x3F), "Azimuth"},
    {make_usage(page::kDigitizer, 0x40), "Altitude"},
    {make_usage(page::kDigitizer, 0x41), "Twist"},
    {make_usage(page::kDigitizer, 0x42), "Tip Switch"},
    {make_usage(page::kDigitizer, 0x44), "Barrel Switch"},
    {make_usage(page::kDigitizer, 0x45), "Eraser"},
    {make_usage(page::kDigitizer, 0x47), "Confidence"},
    {make_usage(page::kDigitizer, 0x48), "Width"},
    {make_usage(page::kDigitizer, 0x49), "Height"},
    {make_usage(page::kDigitizer, 0x51), "Contact Id"},
    {make_usage(page::kDigitizer, 0x54), "Contact Count"},
    {make_usage(page::kDigitizer, 0x55), "Contact Count Maximum"},
    {make_usage(page::kDigitizer, 0x56), "Scan Time"},
    {make_usage(page::kDigitizer, 0x5A), "Secondary Barrel Switch"},
    {make_usage(page::kDigitizer, 0x5B), "Transducer Serial Number"},
};

std::string hex4(unsigned value) {
  char text[8];
  std::snprintf(text, sizeof text, "%04X", value & 0xFFFFu);
  return text;
}

}  // namespace

std::string usage_page_name(std::uint16_t page) {
  switch (page) {
    case page::kGenericDesktop:
      return "Generic Desktop";
    case page::kButton:
      return "Button";
    case page::kDigitizer:
      return "Digitizer";
    default:
      break;
  }
  if (page >= page::kVendorFirst) return "Vendor 0x" + hex4(page);
  return "Page 0x" + hex4(page);
}

std::string usage_name(Usage usage) {
  for (const NamedUsage& named : kNames) {
    if (named.usage == usage) return named.name;
  }
  const std::uint16_t page = usage_page(usage);
  const std::uint16_t id = usage_id(usage);
  if (page == page::kButton) return "Button " + std::to_string(id);
  if (page >= page::kVendorFirst) return "Vendor Usage " + std::to_string(id);
  return "0x" + hex4(page) + ":0x" + hex4(id);
}

}  // namespace impasto::input::hid
