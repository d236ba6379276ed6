#pragma once
// What paint lies at a point of the canvas: the eyedropper's question. An RGB program can only
// answer with a colour; a painting keeps its pigments, so the probe answers with the paint
// itself (which pigments, in what proportions, how thick wet and dry), from which a colour is
// rendered and a brush loaded.
#include <cstddef>
#include <string>
#include <vector>

#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {

// Cells holding less paint than this (mm of height) count as bare: a stroke's smear.
inline constexpr float kProbeBareBelowMm = 1e-3f;

struct PaintProbe {
  std::size_t cells = 0;        // canvas cells inside the probe's disc
  std::size_t wet_cells = 0;    // of them, those whose visible paint is wet
  std::size_t dry_cells = 0;    // ... whose visible paint is the top dry layer holding paint
  double wet_mm = 0.0;          // mean wet paint height over the disc
  double dry_mm = 0.0;          // mean height of all dry layers over the disc
  std::vector<double> pigment;  // per slot: the visible paint's amounts (mm, summed over cells)
  // The visible paint's medium (paint_surface.hpp): each cell's surface medium, mixed by the
  // height of its visible paint (share 0: none of it was mixed with a medium).
  PaintMedium medium;

  bool bare() const { return wet_cells + dry_cells == 0; }
  // Per slot, the share (0..1) of the visible paint's pigment; all zero when bare.
  std::vector<double> shares() const;
};

// The paint within `radius_cells` of the cell centre (x_cells, y_cells); cells outside the
// canvas are left out. In each cell the visible paint is the wet layer where it holds paint,
// else the topmost dry layer that does (what the eye sees, and what a knife would scrape).
// Non-finite coordinates or radius probe nothing.
PaintProbe probe_paint(const Painting& painting, double x_cells, double y_cells,
                       double radius_cells);

}  // namespace impasto::paintcore
