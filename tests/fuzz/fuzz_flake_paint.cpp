// Fuzz target: any bytes as a flake paint file (docs/flakes.md). Nothing may crash, and a
// paint that reads must give finite tables with reflectances in [0, 1] (a stack of 100+ film
// layers once gave NaN pixels). An n,k table it names is looked up beside the bundled flakes,
// and only there (paths are confined to that folder).
#include <impasto/files/data_dir.hpp>
#include <impasto/flakes/flake_file.hpp>
#include <impasto/flakes/flake_tables.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flakes = impasto::flakes;

namespace {

void require_finite_unit(double value) {
  if (!std::isfinite(value) || value < -1e-9 || value > 1.0 + 1e-6) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  flakes::FlakePaint paint;
  try {
    paint = flakes::parse_flake_paint(text, "fuzz.flake", impasto::files::data_dir() / "flakes");
  } catch (const std::runtime_error&) {
    return 0;
  }
  constexpr std::array<double, 3> kWavelengths{450.0, 550.0, 650.0};
  const flakes::FlakeTables tables(paint, kWavelengths);
  for (std::size_t w = 0; w < kWavelengths.size(); ++w)
    for (const double r : tables.reflectance_samples(w)) require_finite_unit(r);
  for (const double c : {0.0, 0.3, 1.0}) {
    require_finite_unit(tables.flake_transmittance(c));
    if (!std::isfinite(tables.projected_area(c))) std::abort();
  }
  return 0;
}
