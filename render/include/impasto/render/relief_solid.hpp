#pragma once
// The relief as a printable solid: a closed, manifold triangle mesh of the paint's top surface
// over the canvas, with sides and a flat back, in millimetres at the painting's real size.
// Flat areas take few triangles: the top is an adaptive quadtree of the corner grid, each leaf
// split until a fan of four triangles from its centre follows the heights within half the
// allowed error, and each leaf is then fanned through every vertex its finer neighbours put
// on its edges, so no crack opens between leaves of different sizes.
//
// Coordinates: x to the right, y up the image (the painting seen from above, +z out of the
// canvas); the top at the paint's height over the ground, the back at z = -base_mm. Triangles
// wind counter-clockwise seen from outside.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "impasto/render/image.hpp"
#include "impasto/render/relief_maps.hpp"

namespace impasto::render {

struct SolidOptions {
  double base_mm = 2.0;        // the slab under the ground (> 0: a solid without paint is closed)
  double relief_scale = 1.0;   // heights multiplied (> 0): an exaggerated relief
  double max_error_mm = 0.05;  // the top's largest height error at the corners (>= 0): a fine
                               // printer's layer
  // At most this many triangles (0: no limit): the error is raised until the mesh fits (the
  // fewest a closed solid of the relief can have, when even that is more).
  std::size_t max_triangles = 0;
};

struct SolidMesh {
  std::vector<std::array<float, 3>> vertices;        // mm
  std::vector<std::array<std::uint8_t, 3>> colours;  // sRGB per vertex, or empty
  std::vector<std::array<std::uint32_t, 3>> triangles;
  double max_error_mm = 0.0;  // the error the top was made with (raised by max_triangles)
};

// The solid of a height grid (surface_heights). The top's vertex heights are those of the
// grid's cell corners: the mean of the cells that share the corner. Throws
// std::invalid_argument for an empty grid or options out of range.
SolidMesh relief_solid(const HeightGrid& heights, const SolidOptions& options);

// Colours each vertex from `display` (an sRGB-encoded render, one pixel a cell of the grid the
// mesh was made from): the pixel of the cell nearest the vertex.
void colour_solid(SolidMesh& mesh, const Image& display, double cell_mm);

// Writes by extension, atomically: .stl (binary STL, no colour), .ply (binary little-endian
// PLY with the vertex colours when there are any), .obj (Wavefront OBJ, text, "v x y z r g b"
// with colours). Throws std::runtime_error naming the file for another extension.
void write_solid(const std::filesystem::path& path, const SolidMesh& mesh);

}  // namespace impasto::render
