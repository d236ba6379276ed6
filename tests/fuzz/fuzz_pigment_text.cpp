// Fuzz target: any bytes as a pigment file's text (docs/pigments.md: '# quantity:
// kubelka_munk', '# name:', columns wavelength_nm, K, S). Nothing may crash, and a pigment
// that reads has finite, non-negative K and S at every wavelength it gives.
#include <impasto/data/pigment_text.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace data = impasto::data;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(bytes), size);
  try {
    const data::Pigment pigment = data::parse_pigment_text(text, "fuzz.csv");
    for (const auto* spectrum : {&pigment.K, &pigment.S})
      for (const double value : spectrum->values)
        if (!std::isfinite(value) || value < 0.0) std::abort();
  } catch (const std::runtime_error&) {
  }
  return 0;
}
