#pragma once
// The relief as data, for 3D and print: the height map (the surface's height in mm, cell by
// cell) and the normal map (tangent-space normals). Both are written atomically.
//
// Height map: by extension,
//   .png  16-bit greyscale, height_mm = offset + value * step, with tEXt chunks
//         "impasto:height_offset_mm", "impasto:height_step_mm" (the 65535 steps span the
//         painting's lowest to highest point) and "impasto:cell_mm" (the pixel's size);
//   .exr  32-bit float channel "Z" holding mm, with attribute "impasto:cell_mm".
// Normal map: 8-bit RGB PNG, tangent space in the OpenGL convention (+X right, +Y up the image,
// +Z out of the canvas), channel = (n + 1) / 2, with no colour chunk (the values are data);
// a tEXt chunk "impasto:normal_convention" says "OpenGL +Y up".
#include <filesystem>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/image.hpp"

namespace impasto::render {

struct HeightGrid {
  int width = 0, height = 0;
  double cell_mm = 0.0;   // the size of a cell (pixel)
  std::vector<float> mm;  // row-major, top row first

  float at(int x, int y) const {
    return mm[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x)];
  }
};

// The surface height of every cell: the canvas weave, the dry layers and the wet paint (mm).
HeightGrid surface_heights(const paintcore::Canvas& canvas);

// Writes the height map by extension (.png or .exr, above); throws std::runtime_error naming
// the file for another extension or a write error.
void write_height_map(const std::filesystem::path& path, const HeightGrid& heights);
// Reads a height map this program wrote back to mm (the PNG through its chunks).
HeightGrid read_height_map(const std::filesystem::path& path);

// Unit normals of the surface (central differences, one-sided at the edges) encoded as above:
// RGB in [0, 1].
Image normal_map(const HeightGrid& heights);
void write_normal_map(const std::filesystem::path& path, const HeightGrid& heights);

}  // namespace impasto::render
