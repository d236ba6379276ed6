#include "impasto/render/colour_recipe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "impasto/data/cie.hpp"
#include "impasto/data/kubelka_munk.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/pigment_swatches.hpp"

namespace impasto::render {

struct RecipeFinder::Candidate {
  std::vector<std::size_t> pigments;
  std::vector<double> shares;
  double delta_e = std::numeric_limits<double>::infinity();
};

namespace {

// sRGB's primaries to XYZ (IEC 61966-2-1), D65 white with Y = 100.
constexpr double kSrgbToXyz[9] = {41.24, 35.76, 18.05, 21.26, 71.52, 7.22, 1.93, 11.92, 95.05};
constexpr data::Xyz kD65{95.047, 100.0, 108.883};

// A part smaller than this is left out of a recipe (half a percent: a painter cannot weigh
// less), and a recipe with more pigments is offered only when it comes this much nearer.
constexpr double kLeastShare = 0.005;
constexpr double kNearerBy = 0.1;

// The grid the search evaluates masstones on (the reference re-evaluates the winner).
std::vector<double> search_grid() {
  return data::wavelength_grid(400.0, 700.0, 10.0);
}

}  // namespace

std::array<double, 3> parse_srgb_colour(const std::string& text) {
  const auto fail = [&]() -> std::array<double, 3> {
    throw std::runtime_error("colour '" + text.substr(0, 40) +
                             "': expected #RRGGBB or R,G,B with each 0-255");
  };
  std::array<double, 3> rgb{};
  std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (hex.size() == 6 && hex.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos) {
    for (std::size_t i = 0; i < 3; ++i)
      rgb[i] = std::stoi(hex.substr(2 * i, 2), nullptr, 16) / 255.0;
    return rgb;
  }
  std::size_t at = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    if (end == std::string::npos || end == at || end - at > 3) return fail();
    const std::string field = text.substr(at, end - at);
    if (field.find_first_not_of("0123456789") != std::string::npos) return fail();
    const int value = std::stoi(field);
    if (value > 255) return fail();
    rgb[i] = value / 255.0;
    at = end + 1;
  }
  return rgb;
}

data::Lab srgb_to_lab(const std::array<double, 3>& encoded) {
  double linear[3];
  for (int i = 0; i < 3; ++i)
    linear[i] = srgb_decoded(std::clamp(encoded[static_cast<std::size_t>(i)], 0.0, 1.0));
  data::Xyz xyz;
  xyz.X = kSrgbToXyz[0] * linear[0] + kSrgbToXyz[1] * linear[1] + kSrgbToXyz[2] * linear[2];
  xyz.Y = kSrgbToXyz[3] * linear[0] + kSrgbToXyz[4] * linear[1] + kSrgbToXyz[5] * linear[2];
  xyz.Z = kSrgbToXyz[6] * linear[0] + kSrgbToXyz[7] * linear[1] + kSrgbToXyz[8] * linear[2];
  return data::xyz_to_lab(xyz, kD65);
}

RecipeFinder::RecipeFinder(std::span<const data::Pigment> palette, const data::Spectrum& light)
    : palette_(palette), reference_(swatch_sampling(light)) {
  const std::vector<double> grid = search_grid();
  for (const data::Pigment& pigment : palette) {
    std::vector<double> k, s;
    for (const double nm : grid) {
      k.push_back(std::max(pigment.K.at(nm), 0.0));
      s.push_back(std::max(pigment.S.at(nm), 1e-9));
    }
    k_.push_back(std::move(k));
    s_.push_back(std::move(s));
  }
  const data::ColorMatchingFunctions& cmf = data::cie1931_2deg();
  double y_white = 0.0;
  for (const double nm : grid) {
    const double e = light.at(nm);
    wx_.push_back(e * cmf.x.at(nm));
    wy_.push_back(e * cmf.y.at(nm));
    wz_.push_back(e * cmf.z.at(nm));
    y_white += wy_.back();
  }
  const double scale = y_white > 0.0 ? 100.0 / y_white : 0.0;
  white_ = {};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    wx_[i] *= scale;
    wy_[i] *= scale;
    wz_[i] *= scale;
    white_.X += wx_[i];
    white_.Y += wy_[i];
    white_.Z += wz_[i];
  }
}

data::Lab RecipeFinder::fast_lab(std::span<const std::size_t> pigments,
                                 std::span<const double> share) const {
  const data::Saunderson surface;
  data::Xyz xyz{};
  for (std::size_t i = 0; i < wx_.size(); ++i) {
    double k = 0.0, s = 0.0;
    for (std::size_t j = 0; j < pigments.size(); ++j) {
      k += share[j] * k_[pigments[j]][i];
      s += share[j] * s_[pigments[j]][i];
    }
    const double r = surface.to_measured(data::reflectance_infinite(k, s));
    xyz.X += r * wx_[i];
    xyz.Y += r * wy_[i];
    xyz.Z += r * wz_[i];
  }
  return data::xyz_to_lab(xyz, white_);
}

RecipeFinder::Candidate RecipeFinder::best_pair(std::size_t a, std::size_t b,
                                                const data::Lab& target) const {
  const std::array<std::size_t, 2> p{a, b};
  const auto error = [&](double t) {
    const std::array<double, 2> share{t, 1.0 - t};
    return data::ciede2000(fast_lab(p, share), target);
  };
  // A coarse scan, then a golden-section search in the bracket around its best.
  constexpr int kSteps = 40;
  int best = 1;
  double best_error = std::numeric_limits<double>::infinity();
  for (int i = 1; i < kSteps; ++i) {
    const double e = error(static_cast<double>(i) / kSteps);
    if (e < best_error) best_error = e, best = i;
  }
  double lo = (best - 1.0) / kSteps, hi = (best + 1.0) / kSteps;
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 24; ++i) {
    const double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
    if (error(m1) < error(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  const double t = 0.5 * (lo + hi);
  return {{a, b}, {t, 1.0 - t}, error(t)};
}

RecipeFinder::Candidate RecipeFinder::best_triple(const std::array<std::size_t, 3>& p,
                                                  const data::Lab& target) const {
  const auto error = [&](double u, double v) {
    const std::array<double, 3> share{u, v, 1.0 - u - v};
    return data::ciede2000(fast_lab(p, share), target);
  };
  // A scan of the simplex's inside, then a pattern search that halves its step.
  constexpr int kSteps = 16;
  double bu = 1.0 / 3, bv = 1.0 / 3, be = error(bu, bv);
  for (int i = 1; i < kSteps; ++i)
    for (int j = 1; i + j < kSteps; ++j) {
      const double u = static_cast<double>(i) / kSteps, v = static_cast<double>(j) / kSteps;
      const double e = error(u, v);
      if (e < be) be = e, bu = u, bv = v;
    }
  for (double step = 0.5 / kSteps; step > 1e-4; step *= 0.5) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [du, dv] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}}) {
        const double u = bu + du * step, v = bv + dv * step;
        if (u <= 0.0 || v <= 0.0 || u + v >= 1.0) continue;
        const double e = error(u, v);
        if (e < be) be = e, bu = u, bv = v, moved = true;
      }
    }
  }
  return {{p[0], p[1], p[2]}, {bu, bv, 1.0 - bu - bv}, be};
}

Recipe RecipeFinder::evaluate(std::vector<RecipePart> parts, const data::Lab& target) const {
  double total = 0.0;
  for (const RecipePart& part : parts) total += part.share;
  for (RecipePart& part : parts) part.share = total > 0.0 ? part.share / total : 0.0;
  std::sort(parts.begin(), parts.end(),
            [](const RecipePart& a, const RecipePart& b) { return a.share > b.share; });
  // The reference: the swatches' (every nm, the renderer's flat layer).
  std::vector<const data::Pigment*> pigments;
  std::vector<double> shares;
  for (const RecipePart& part : parts) {
    pigments.push_back(&palette_[part.pigment]);
    shares.push_back(part.share);
  }
  const SwatchColour colour = describe_colour(
      "masstone", seen_through_surface(mix_reflectance(pigments, shares, reference_)), reference_);
  Recipe recipe;
  recipe.parts = std::move(parts);
  recipe.lab = colour.lab;
  recipe.srgb = colour.srgb;
  recipe.delta_e00 = data::ciede2000(colour.lab, target);
  return recipe;
}

std::vector<Recipe> RecipeFinder::find(const data::Lab& target) const {
  const std::size_t n = palette_.size();
  std::vector<Recipe> recipes;
  if (n == 0) return recipes;
  // Ones.
  std::vector<Candidate> singles;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<std::size_t, 1> p{i};
    const std::array<double, 1> share{1.0};
    singles.push_back({{i}, {1.0}, data::ciede2000(fast_lab(p, share), target)});
  }
  const auto nearer = [](const Candidate& a, const Candidate& b) { return a.delta_e < b.delta_e; };
  std::sort(singles.begin(), singles.end(), nearer);
  // A candidate as the reference sees it, less the parts too small to weigh out (under
  // kLeastShare); kept only when it comes nearer than the fewer pigments before it.
  const auto add = [&](const Candidate& c) {
    std::vector<RecipePart> parts;
    for (std::size_t j = 0; j < c.pigments.size(); ++j)
      if (c.shares[j] >= kLeastShare) parts.push_back({c.pigments[j], c.shares[j]});
    Recipe recipe = evaluate(std::move(parts), target);
    if (recipes.empty() || (recipe.parts.size() > recipes.back().parts.size() &&
                            recipe.delta_e00 < recipes.back().delta_e00 - kNearerBy))
      recipes.push_back(std::move(recipe));
  };
  add(singles.front());
  if (n < 2) return recipes;
  // Twos, every pair.
  std::vector<Candidate> pairs;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) pairs.push_back(best_pair(a, b, target));
  std::sort(pairs.begin(), pairs.end(), nearer);
  add(pairs.front());
  if (n < 3) return recipes;
  // Threes among the pigments of the nearest pairs and singles (a dozen or so).
  std::vector<std::size_t> chosen;
  const auto choose = [&](std::size_t i) {
    if (std::find(chosen.begin(), chosen.end(), i) == chosen.end()) chosen.push_back(i);
  };
  for (std::size_t k = 0; k < pairs.size() && chosen.size() < 10; ++k)
    for (const std::size_t i : pairs[k].pigments) choose(i);
  for (std::size_t k = 0; k < singles.size() && k < 3; ++k) choose(singles[k].pigments[0]);
  std::sort(chosen.begin(), chosen.end());
  Candidate best;
  for (std::size_t a = 0; a < chosen.size(); ++a)
    for (std::size_t b = a + 1; b < chosen.size(); ++b)
      for (std::size_t c = b + 1; c < chosen.size(); ++c) {
        Candidate t = best_triple({chosen[a], chosen[b], chosen[c]}, target);
        if (t.delta_e < best.delta_e) best = std::move(t);
      }
  if (best.pigments.empty()) return recipes;
  add(best);
  return recipes;
}

}  // namespace impasto::render
