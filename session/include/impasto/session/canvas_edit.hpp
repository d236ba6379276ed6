#pragma once
// The work of `impasto edit` (the canvas's size, a coat of varnish) and `impasto export` (an image
// at a larger scale, the height and normal maps), apart from their options so that tests call them.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <impasto/render/relief_solid.hpp>
#include "impasto/paintcore/canvas_reframe.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/crack_close_up.hpp"
#include "impasto/render/render_settings.hpp"

namespace impasto::session {

struct CanvasEdit {
  std::optional<render::CellRegion> crop;   // first: the rectangle kept
  std::optional<std::pair<int, int>> size;  // then: the new size, width x height in cells
  paintcore::CanvasAnchor anchor = paintcore::CanvasAnchor::kCenter;  // where the old canvas sits
  // Last: a coat of varnish (paint_surface.hpp) over the region's cells (of the canvas after
  // the crop and resize), or over the whole painting.
  std::optional<paintcore::Finish> varnish;
  double varnish_thickness_mm = 0.03;
  std::optional<render::CellRegion> varnish_region;
  // Then: let the wet paint and varnish dry by this fraction (Painting::dry), or not at all.
  std::optional<double> dry;
};

struct CanvasEditResult {
  int old_width = 0, old_height = 0, width = 0, height = 0;
  paintcore::PaintTotals cut;   // mm^3 cut away, by slot
  bool reframed = false;        // a crop or a resize was asked for
  std::string varnished;        // "0.03 mm of satin varnish over 50x40 cells", or empty
  std::optional<double> dried;  // the fraction dried last
  // "200x150 -> 100x90 cells; cut away 1.25 mm^3 of paint (Red Oxide 0.6, ...)"
  std::string summary(const paintcore::Painting& painting) const;
};

// Applies the crop, the resize, the varnish, then the drying; each is one undo step. Throws
// naming the option.
CanvasEditResult edit_canvas(paintcore::Painting& painting, const CanvasEdit& edit);

struct ExportRequest {
  int scale = 1;                     // 1, 2 or 4 (any of 1..16): pixels per cell
  std::filesystem::path image;       // the render (.png or .exr), or empty
  std::filesystem::path height_map;  // .png (16-bit) or .exr (float mm), or empty
  std::filesystem::path normal_map;  // .png, or empty
  render::RenderSettings settings;   // the image's light and look
  int supersample = 1;               // the image's samples a pixel each way (1..4), box-filtered
  // The relief as a closed solid (render/relief_solid.hpp), each by its extension: .stl, .ply
  // or .obj (the last two with the render's colours); with its options.
  std::vector<std::filesystem::path> solids;
  render::SolidOptions solid;
};

struct ExportReport {
  std::size_t solid_triangles = 0, solid_vertices = 0;  // of the solid, when one was written
  double solid_error_mm = 0.0;  // its top's error (raised by solid.max_triangles)
};

// Writes what the request names; the maps and the solid at the same scale as the image (their
// pixel is a cell of the refined canvas: Painting::refined). Throws std::runtime_error naming
// the file.
ExportReport export_painting(const paintcore::Painting& painting, const ExportRequest& request);

}  // namespace impasto::session
