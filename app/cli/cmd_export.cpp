// impasto export: an image at a larger scale with a smooth relief, and the relief as data for
// 3D and print — the height map and the normal map (canvas_edit.hpp does the work).
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/render_painting.hpp>

#include <iostream>
#include <memory>
#include <string>

#include "command.hpp"
#include "impasto/session/canvas_edit.hpp"
#include "impasto/util/text.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::export_cmd {
namespace {

struct ExportArgs {
  std::string painting;
  session::ExportRequest request;
  std::string image, height_map, normal_map, stl, ply, obj;
};

const CommandRegistrar registrar("export", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand(
      "export",
      "Write a painting at a larger scale, its height map, its normal map and its relief as a "
      "solid (STL, PLY, OBJ)");
  auto args = std::make_shared<ExportArgs>();
  cmd->add_option("painting", args->painting, "The .impasto painting file")->required();
  cmd->add_option("--scale", args->request.scale,
                  "Pixels per cell (1, 2, 4, ... 16): heights and paint interpolated smoothly "
                  "(Catmull-Rom) and shaded at the finer grid; the maps too")
      ->check(finite_range(1, 16))
      ->capture_default_str();
  cmd->add_option("--supersample", args->request.supersample,
                  "Samples a pixel each way (1, 2, 4): the image shaded that much finer and "
                  "box-filtered in linear light, so weave and furrows finer than a pixel do not "
                  "alias (docs/canvas-and-export.md: cost and error)")
      ->check(finite_range(1, render::kMaxSupersample))
      ->capture_default_str();
  add_out_option(*cmd, args->image,
                 "the render at --scale, default light and settings (impasto render has them "
                 "all; the window's Image menu uses its light)");
  cmd->add_option("--height-map", args->height_map,
                  "The surface height in mm: .png (16-bit grey; offset, step and cell size in "
                  "its tEXt chunks) or .exr (float mm)");
  cmd->add_option("--normal-map", args->normal_map,
                  "Tangent-space normals, OpenGL convention (+Y up): 8-bit RGB .png");
  cmd->add_option("--stl", args->stl,
                  "The relief as a closed solid for 3D printing, in mm at the painting's size: "
                  "the paint's top, sides and a flat back (binary STL)");
  cmd->add_option("--ply", args->ply, "The solid with the render's colours (binary PLY)");
  cmd->add_option("--obj", args->obj, "The solid with the render's colours (Wavefront OBJ)");
  cmd->add_option("--base-mm", args->request.solid.base_mm,
                  "The solid's slab under the ground's lowest point, mm")
      ->check(finite_range(0.01, 1000.0))
      ->capture_default_str();
  cmd->add_option("--relief-scale", args->request.solid.relief_scale,
                  "The solid's heights multiplied: an exaggerated relief")
      ->check(finite_range(0.01, 1000.0))
      ->capture_default_str();
  cmd->add_option("--max-error-mm", args->request.solid.max_error_mm,
                  "The solid's largest height error at the cell corners, mm: flat areas take few "
                  "triangles (0: every corner)")
      ->check(finite_range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--max-triangles", args->request.solid.max_triangles,
                  "At most this many triangles in the solid: its error is raised until it fits "
                  "(0: no limit)")
      ->check(finite_range(std::size_t{0}, std::size_t{1} << 31))
      ->capture_default_str();
  cmd->callback([args] {
    session::ExportRequest request = args->request;
    request.image = args->image;
    request.height_map = args->height_map;
    request.normal_map = args->normal_map;
    for (const std::string* solid : {&args->stl, &args->ply, &args->obj})
      if (!solid->empty()) request.solids.emplace_back(*solid);
    const paintcore::Painting painting = paintcore::Painting::load(args->painting, 0, false);
    const session::ExportReport report = export_painting(painting, request);
    for (const std::string* file : {&args->image, &args->height_map, &args->normal_map})
      if (!file->empty()) note("wrote " + *file);
    for (const auto& solid : request.solids)
      note("wrote " + solid.string() + ": " + std::to_string(report.solid_triangles) +
           " triangles, " + std::to_string(report.solid_vertices) + " vertices, within " +
           util::number_text(report.solid_error_mm, 3) + " mm of the relief");
  });
});

}  // namespace
}  // namespace impasto::app::export_cmd
