#include "impasto/render/surface_settings.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::render {

void validate(const SurfaceSettings& s) {
  const auto require = [](bool ok, const char* field, double value, const char* expected) {
    if (!ok) {
      throw std::runtime_error(std::string("render settings: surface.") + field + " = " +
                               std::to_string(value) + " (expected " + expected + ")");
    }
  };
  require(s.binder_index >= 1.0 && s.binder_index <= 3.0, "binder_index", s.binder_index,
          "in [1, 3]");
  require(s.varnish_index >= 1.0 && s.varnish_index <= 3.0, "varnish_index", s.varnish_index,
          "in [1, 3]");
  require(s.medium_amount >= 0.0 && s.medium_amount <= 1.0, "medium_amount", s.medium_amount,
          "in [0, 1]");
  require(s.subcell_slope_rms >= 0.0 && s.subcell_slope_rms <= 1.0, "subcell_slope_rms",
          s.subcell_slope_rms, "in [0, 1]");
  require(s.subsurface_min_cells > 0.0 && s.subsurface_min_cells <= 100.0, "subsurface_min_cells",
          s.subsurface_min_cells, "in (0, 100]");
}

SurfaceModel parse_surface_model(std::string_view text) {
  return util::parse_name(kSurfaceModelNames, text, "surface model");
}

surface::Finish parse_finish(std::string_view text) {
  return util::parse_name(surface::kFinishNames, text, "finish");
}

std::optional<surface::Finish> parse_varnish(std::string_view text) {
  if (text == "none") return std::nullopt;
  return parse_finish(text);
}

}  // namespace impasto::render
