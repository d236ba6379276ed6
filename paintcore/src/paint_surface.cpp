#include "impasto/paintcore/paint_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace impasto::paintcore {

FinishRoughness film_roughness(Finish finish) {
  switch (finish) {
    case Finish::gloss:
      return {0.01, 4.0};
    case Finish::satin:
      return {0.08, 4.0};
    case Finish::matte:
      return {1.5, 5.0};
  }
  return {};
}

double finish_log_rms(Finish finish) {
  return std::log10(film_roughness(finish).rms_um);
}

FinishRoughness roughness_at_log_rms(double log_rms) {
  // The finishes ordered by roughness: gloss < satin < matte.
  constexpr std::array<Finish, kFinishCount> kOrder{Finish::gloss, Finish::satin, Finish::matte};
  const double rms = std::pow(10.0, log_rms);
  const FinishRoughness first = film_roughness(kOrder.front());
  if (log_rms <= finish_log_rms(kOrder.front())) return {rms, first.correlation_um};
  for (std::size_t k = 1; k < kOrder.size(); ++k) {
    const double lo = finish_log_rms(kOrder[k - 1]);
    const double hi = finish_log_rms(kOrder[k]);
    if (log_rms <= hi) {
      const double t = (log_rms - lo) / (hi - lo);
      const double a = film_roughness(kOrder[k - 1]).correlation_um;
      const double b = film_roughness(kOrder[k]).correlation_um;
      return {rms, a * std::pow(b / a, t)};
    }
  }
  return {rms, film_roughness(kOrder.back()).correlation_um};
}

double varnish_levelled_share(double thickness_mm) {
  const double t3 = std::pow(std::max(thickness_mm, 0.0), 3.0);
  return t3 / (t3 + std::pow(kVarnishHalfLevelledMm, 3.0));
}

std::string medium_spelling(const Medium& medium) {
  std::string out(finish_name(medium.finish));
  if (medium.amount != 1.0) {
    char amount[32];
    for (int digits = 6; digits <= 17; ++digits) {  // the shortest that reads back the same
      std::snprintf(amount, sizeof amount, ":%.*g", digits, medium.amount);
      if (std::stod(amount + 1) == medium.amount) break;
    }
    out += amount;
  }
  return out;
}

void validate(const Medium& medium) {
  if (static_cast<int>(medium.finish) >= kFinishCount)
    throw std::runtime_error("medium: field 'finish' is not a finish");
  if (!(medium.amount >= 0.0 && medium.amount <= 1.0))
    throw std::runtime_error("medium: field 'amount' must be in [0, 1], got " +
                             std::to_string(medium.amount));
}

double medium_log_rms(const Medium& medium) {
  const double tube = finish_log_rms(Finish::satin);
  return tube + medium.amount * (finish_log_rms(medium.finish) - tube);
}

PaintMedium paint_medium(const Medium& medium) {
  return {1.0f, static_cast<float>(medium_log_rms(medium))};
}

std::optional<Medium> loadable_medium(const PaintMedium& paint) {
  if (!(paint.share >= 0.5f)) return std::nullopt;
  const double tube = finish_log_rms(Finish::satin);
  const double offset = paint.log_rms - tube;
  // Tube paint itself, to float precision: satin.
  if (std::abs(offset) < 1e-6) return Medium{Finish::satin, 1.0};
  const Finish finish = offset < 0.0 ? Finish::gloss : Finish::matte;
  return Medium{finish, std::clamp(offset / (finish_log_rms(finish) - tube), 0.0, 1.0)};
}

PaintMedium mix(const PaintMedium& a, double a_volume, const PaintMedium& b, double b_volume) {
  const double va = std::max(a_volume, 0.0), vb = std::max(b_volume, 0.0);
  const double volume = va + vb;
  if (!(volume > 0.0)) return a;
  const double medium_a = va * a.share, medium_b = vb * b.share;
  PaintMedium out;
  out.share = static_cast<float>(std::clamp((medium_a + medium_b) / volume, 0.0, 1.0));
  const double medium = medium_a + medium_b;
  // Where neither part has a medium, the roughness keeps a's (it is not read at share 0).
  out.log_rms = medium > 0.0
                    ? static_cast<float>((medium_a * a.log_rms + medium_b * b.log_rms) / medium)
                    : a.log_rms;
  return out;
}

void copy_cell_surface(const Tile* from, int from_cell, Tile& to, int to_cell) {
  if (from == nullptr) return;
  const auto f = static_cast<std::size_t>(from_cell), t = static_cast<std::size_t>(to_cell);
  if (!from->medium.empty()) {
    if (to.medium.empty()) to.medium.assign(std::size_t{kMediumPlanes} * kTileCells, 0.0f);
    for (std::size_t k = 0; k < kMediumPlanes; ++k)
      to.medium[k * kTileCells + t] = from->medium[k * kTileCells + f];
  }
  if (!from->varnish.empty()) {
    if (to.varnish.empty()) to.varnish.assign(std::size_t{kVarnishPlanes} * kTileCells, 0.0f);
    for (std::size_t k = 0; k < kVarnishPlanes; ++k)
      to.varnish[k * kTileCells + t] = from->varnish[k * kTileCells + f];
  }
}

CellSurface cell_surface(const Tile* tile, int cell) {
  CellSurface out;
  if (tile == nullptr) return out;
  const auto c = static_cast<std::size_t>(cell);
  if (!tile->medium.empty()) {
    out.medium.share = tile->medium[c];
    out.medium.log_rms = tile->medium[kTileCells + c];
  }
  if (!tile->varnish.empty()) {
    out.varnish_mm = tile->varnish[c];
    out.varnish_wet_mm = tile->varnish[kTileCells + c];
    out.varnish_log_rms = tile->varnish[2 * kTileCells + c];
  }
  return out;
}

}  // namespace impasto::paintcore
