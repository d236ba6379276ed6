#pragma once
// Ways to crack a painting: the craquelure generator (a connected network of polygonal
// islands), a crack brush stamping along a polyline, and crack maps read from or written to
// PNG images (grey = depth). All deterministic for a given seed and input.
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "impasto/cracks/crack_map.hpp"

namespace impasto::cracks {

// The dry paint film over the canvas: thickness (mm) of each dry layer, bottom first, one
// value per cell in row-major order. With no layers, uniform_thickness_mm is used.
struct PaintFilm {
  std::vector<std::span<const float>> layer_thickness_mm;
  double uniform_thickness_mm = 0.2;
};

struct CraquelureSettings {
  std::uint64_t seed = 1;
  double island_size_mm = 3.0;  // mean spacing of the islands (Voronoi sites)
  double jitter = 0.9;          // 0: sites on a square grid, 1: anywhere in their grid cell
  double age_years = 150.0;
  // The film's shrinkage strain grows as max_strain (1 - exp(-age / strain_time_years)).
  double max_strain = 0.02;
  double strain_time_years = 60.0;
  // Cracks deepen from the top and reach the ground after this age.
  double years_to_ground = 80.0;
  // Crack width grows with the film thickness relative to this reference.
  double reference_thickness_mm = 0.2;
  double width_variation = 0.35;  // each crack's width varies by up to this fraction
  CavityShape shape = CavityShape::VGroove;
};

// Crack geometry of one cell from the film there (thickness t_mm) and the settings:
//   opening 2R = strain(age) * island_size * (t / t_ref) * variation,
//   depth L = t * min(1, age / years_to_ground).
struct CrackSize {
  double depth_mm, half_width_mm;
};
CrackSize craquelure_crack_size(const CraquelureSettings& s, double thickness_mm, double variation);

// Fills `map` with a craquelure network: the edges of a jittered Voronoi diagram of island
// sites. A cell is cracked when an edge crosses it (its four corners do not all lie in the
// same island, exact since islands are convex). Fragments cut off by the canvas border are
// dropped, so the new network is one 8-connected piece; cracks already in the map stay
// (where they meet, the deeper wins). Cells where the film is thinner than 1 um stay
// uncracked. Throws std::runtime_error for bad settings, a film whose size does not match
// the map, or a thickness that is negative or not finite.
void generate_craquelure(CrackMap& map, const PaintFilm& film, const CraquelureSettings& s);

// A crack drawn by hand: cells within R + cell/2 of the polyline (points in mm on the
// canvas) become cracks of the given shape and size; where cracks overlap the deeper wins.
struct CrackStroke {
  std::vector<std::array<double, 2>> points_mm;
  CavityShape shape = CavityShape::VGroove;
  double depth_mm = 0.1;
  double half_width_mm = 0.05;
  std::uint8_t exposed_layer = kCanvasGround;
};
void stamp_crack(CrackMap& map, const CrackStroke& stroke);

// A crack map from a grey PNG: grey level g (0..max) is depth g / max * max_depth_mm, 0 is
// no crack; half-width = depth / depth_to_half_width. Colour images are converted to grey.
struct CrackImageSettings {
  double cell_mm = 0.1;
  double max_depth_mm = 0.5;
  double depth_to_half_width = 4.0;  // L / R
  CavityShape shape = CavityShape::VGroove;
  std::uint8_t exposed_layer = kCanvasGround;
};
CrackMap read_crack_png(const std::filesystem::path& path, const CrackImageSettings& s);
// Writes the depths as a 16-bit grey PNG (max_depth_mm is white).
void write_crack_png(const CrackMap& map, const std::filesystem::path& path, double max_depth_mm);

}  // namespace impasto::cracks
