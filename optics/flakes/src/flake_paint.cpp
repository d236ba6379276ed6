#include "impasto/flakes/flake_paint.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impasto/flakes/fresnel.hpp"

namespace impasto::flakes {

double OrientationDistribution::relative_density(double beta_rad) const {
  if (kind == Kind::gaussian) {
    const double x = beta_rad / gaussian_sd_rad;
    return std::exp(-0.5 * x * x);
  }
  if (table_beta_rad.empty() || beta_rad > table_beta_rad.back()) return 0.0;
  const auto upper = std::upper_bound(table_beta_rad.begin(), table_beta_rad.end(), beta_rad);
  if (upper == table_beta_rad.begin()) return table_density.front();
  if (upper == table_beta_rad.end()) return table_density.back();
  const auto i = static_cast<std::size_t>(upper - table_beta_rad.begin());
  const double f = (beta_rad - table_beta_rad[i - 1]) / (table_beta_rad[i] - table_beta_rad[i - 1]);
  return table_density[i - 1] + f * (table_density[i] - table_density[i - 1]);
}

double OrientationDistribution::support_rad() const {
  constexpr double kHalfPi = std::numbers::pi / 2;
  if (kind == Kind::gaussian) return std::min(kHalfPi, 9.0 * gaussian_sd_rad);  // e^{-40.5}
  return table_beta_rad.empty() ? 0.0 : std::min(kHalfPi, table_beta_rad.back());
}

double FilmMaterial::index_at(double wavelength_nm) const {
  return name == "rutile" ? rutile_index(wavelength_nm) : constant_index;
}

FilmOptics FlakeCoating::optics(double wavelength_nm, double cos_alpha, double binder_index) const {
  if (kind == Kind::thin_film) {
    std::vector<FilmLayer> stack;
    stack.reserve(layers.size());
    for (const FilmLayerSpec& layer : layers) {
      stack.push_back({layer.material.index_at(wavelength_nm), layer.thickness_nm});
    }
    if (core_index > 0.0) {
      return coated_core_optics(
          thin_film_optics(stack, binder_index, core_index, wavelength_nm, cos_alpha));
    }
    return thin_film_optics(stack, binder_index, binder_index, wavelength_nm, cos_alpha);
  }
  // Metal: interpolate n and k, constant past the ends of the table.
  const auto upper = std::upper_bound(wavelengths_nm.begin(), wavelengths_nm.end(), wavelength_nm);
  std::size_t i = static_cast<std::size_t>(upper - wavelengths_nm.begin());
  double nn = 0, kk = 0;
  if (i == 0) {
    nn = n.front(), kk = k.front();
  } else if (i == wavelengths_nm.size()) {
    nn = n.back(), kk = k.back();
  } else {
    const double f =
        (wavelength_nm - wavelengths_nm[i - 1]) / (wavelengths_nm[i] - wavelengths_nm[i - 1]);
    nn = n[i - 1] + f * (n[i] - n[i - 1]);
    kk = k[i - 1] + f * (k[i] - k[i - 1]);
  }
  const double r =
      fresnel_conductor(cos_alpha, std::complex<double>(nn, kk) / binder_index).unpolarised();
  return {r, 0.0};
}

void validate(const FlakePaint& paint) {
  auto require = [&](bool ok, const char* field) {
    if (!ok) throw std::runtime_error("flake paint '" + paint.name + "': bad " + field);
  };
  auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  auto non_negative = [](double x) { return x >= 0.0 && std::isfinite(x); };
  require(positive(paint.area_density_per_mm), "area_density_per_mm");
  require(positive(paint.flake_area_mean_mm2), "flake_area_mean_mm2");
  require(non_negative(paint.flake_area_sd_mm2), "flake_area_sd_mm2");
  require(paint.binder_index >= 1.0 && paint.binder_index <= 3.0, "binder_ior");
  require(non_negative(paint.binder_absorption_per_mm), "binder_absorption_per_mm");
  require(non_negative(paint.rayleigh_weight_per_mm), "rayleigh_weight_per_mm");
  const OrientationDistribution& o = paint.orientation;
  if (o.kind == OrientationDistribution::Kind::gaussian) {
    require(positive(o.gaussian_sd_rad), "orientation_sd_deg");
  } else {
    require(o.table_beta_rad.size() >= 2 && o.table_beta_rad.size() == o.table_density.size(),
            "orientation table");
  }
  const FlakeCoating& c = paint.coating;
  if (c.kind == FlakeCoating::Kind::metal) {
    require(!c.wavelengths_nm.empty() && c.n.size() == c.wavelengths_nm.size() &&
                c.k.size() == c.wavelengths_nm.size(),
            "nk_table");
  } else {
    require(!c.layers.empty(), "film_layer");
  }
}

}  // namespace impasto::flakes
