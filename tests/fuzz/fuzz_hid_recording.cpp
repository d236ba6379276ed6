// Fuzz target: any bytes as a hid-recorder capture, then its reports through its tablet's
// decoder. Nothing may crash; captures that read must write back to the same capture.
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_tablet.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace hid = impasto::input::hid;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hid::HidRecording capture;
  try {
    std::istringstream in(text);
    capture = hid::parse_hid_recording(in, "fuzz");
  } catch (const impasto::input::InputFormatError&) {
    return 0;
  }
  try {
    (void)hid::decode_recording(capture);
  } catch (const impasto::input::InputFormatError&) {
  } catch (const hid::UnsupportedTablet&) {
  }
  return 0;
}
