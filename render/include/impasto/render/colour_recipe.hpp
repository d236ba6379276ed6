#pragma once
// A colour target's recipe: the mix of at most three pigments of a palette whose masstone,
// under a light, comes nearest a colour the painter chose (the Kubelka–Munk inverse a painter
// does by eye). The masstone as the swatches compute it (pigment_swatches.hpp): R∞ of the
// concentration-weighted K and S, seen through the paint's surface (Saunderson), its L*a*b*
// relative to the light's white, the colour as an eye adapted to that light sees it. The
// target is an sRGB colour as a display shows it: its L*a*b* relative to D65. The distance is
// CIEDE2000.
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "impasto/data/colorimetry.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

struct RecipePart {
  std::size_t pigment = 0;  // index into the palette
  double share = 0.0;       // of the mix; the parts of a recipe add up to 1
};

struct Recipe {
  std::vector<RecipePart> parts;  // largest share first
  double delta_e00 = 0.0;         // from the target
  data::Lab lab;                  // the masstone, relative to the light's white
  std::array<double, 3> srgb{};   // the masstone as the display shows it (encoded, clamped)
};

// "#RRGGBB", "RRGGBB" or "R,G,B" (0..255 each) as encoded sRGB in [0, 1]; throws
// std::runtime_error quoting the text otherwise.
std::array<double, 3> parse_srgb_colour(const std::string& text);
// An encoded sRGB colour (each in [0, 1]) as L*a*b* relative to D65.
data::Lab srgb_to_lab(const std::array<double, 3>& encoded);

class RecipeFinder {
 public:
  // The palette's pigments (K and S on any grid) and the light they are seen under.
  RecipeFinder(std::span<const data::Pigment> palette, const data::Spectrum& light);

  // The nearest recipe of one pigment, then of two and of three where each comes nearer than
  // the one before (by a tenth of a CIEDE2000 unit, its parts each at least half a percent):
  // how much each more pigment buys is the painter's to weigh. Pairs are searched whole; the
  // threes among the pigments of the nearest pairs and singles.
  std::vector<Recipe> find(const data::Lab& target) const;
  // The masstone of a mix as the reference computes it (parts need not add up to 1).
  Recipe evaluate(std::vector<RecipePart> parts, const data::Lab& target) const;

 private:
  struct Candidate;
  // L*a*b* of the masstone of shares `share` of pigments `pigments` on the search's grid.
  data::Lab fast_lab(std::span<const std::size_t> pigments, std::span<const double> share) const;
  Candidate best_pair(std::size_t a, std::size_t b, const data::Lab& target) const;
  Candidate best_triple(const std::array<std::size_t, 3>& p, const data::Lab& target) const;

  std::span<const data::Pigment> palette_;
  SpectralSampling reference_;  // evaluate()'s: the swatches' (pigment_swatches.hpp)
  // The search's grid: every 10 nm from 400 to 700; per pigment K and S there, and the
  // light times each colour-matching function (Y of the white = 100).
  std::vector<std::vector<double>> k_, s_;
  std::vector<double> wx_, wy_, wz_;
  data::Xyz white_;
};

}  // namespace impasto::render
