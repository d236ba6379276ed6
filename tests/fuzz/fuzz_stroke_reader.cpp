// Fuzz target: any bytes as a stroke file (native, libmypaint .dat, BDALab .svc). Nothing
// may crash; a native file that reads must write back and read again to the same events.
#include <impasto/input/stroke_file.hpp>
#include <impasto/input/stroke_import.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace input = impasto::input;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream in(text);
    const input::StrokeFile file = input::parse_strokes(in, "fuzz");
    std::stringstream written;
    input::format_strokes(written, file);
    if (input::parse_strokes(written, "rewritten") != file) std::abort();  // not round-trip
  } catch (const input::InputFormatError&) {
  }
  try {
    std::istringstream in(text);
    (void)input::parse_mypaint_dat(in, "fuzz.dat");
  } catch (const input::InputFormatError&) {
  }
  try {
    std::istringstream in(text);
    (void)input::parse_bdalab_svc(in, "fuzz.svc");
  } catch (const input::InputFormatError&) {
  }
  return 0;
}
