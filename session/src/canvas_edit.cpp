#include "impasto/session/canvas_edit.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "impasto/render/relief_maps.hpp"
#include "impasto/render/relief_solid.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/util/text.hpp"

namespace impasto::session {

CanvasEditResult edit_canvas(paintcore::Painting& painting, const CanvasEdit& edit) {
  CanvasEditResult result;
  result.old_width = painting.canvas().width_cells();
  result.old_height = painting.canvas().height_cells();
  const auto add_cut = [&](const paintcore::PaintTotals& cut) {
    result.cut.volume += cut.volume;
    if (result.cut.pigment.size() < cut.pigment.size())
      result.cut.pigment.resize(cut.pigment.size());
    for (std::size_t s = 0; s < cut.pigment.size(); ++s) result.cut.pigment[s] += cut.pigment[s];
  };
  if (edit.crop) {
    const render::CellRegion& r = *edit.crop;
    if (r.x < 0 || r.y < 0 || r.w < 1 || r.h < 1 || r.x + r.w > result.old_width ||
        r.y + r.h > result.old_height)
      throw std::runtime_error(
          "--crop " + std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.w) +
          "," + std::to_string(r.h) + ": the rectangle must lie inside the " +
          std::to_string(result.old_width) + "x" + std::to_string(result.old_height) + " canvas");
    add_cut(painting.reframe_canvas(paintcore::crop_frame(r.x, r.y, r.w, r.h)));
  }
  if (edit.size) {
    const paintcore::Canvas& c = painting.canvas();
    add_cut(painting.reframe_canvas(paintcore::anchored_frame(
        c.width_cells(), c.height_cells(), edit.size->first, edit.size->second, edit.anchor)));
  }
  result.width = painting.canvas().width_cells();
  result.height = painting.canvas().height_cells();
  if (edit.varnish_region && !edit.varnish)
    throw std::runtime_error("--region: says where a varnish goes (give --varnish FINISH)");
  if (edit.varnish) {
    paintcore::CellRect cells{0, 0, result.width, result.height};
    if (edit.varnish_region) {
      const render::CellRegion& r = *edit.varnish_region;
      if (r.x < 0 || r.y < 0 || r.w < 1 || r.h < 1 || r.x + r.w > result.width ||
          r.y + r.h > result.height)
        throw std::runtime_error("--region " + std::to_string(r.x) + "," + std::to_string(r.y) +
                                 "," + std::to_string(r.w) + "," + std::to_string(r.h) +
                                 ": the rectangle must lie inside the " +
                                 std::to_string(result.width) + "x" +
                                 std::to_string(result.height) + " canvas");
      cells = {r.x, r.y, r.x + r.w, r.y + r.h};
    }
    if (!(edit.varnish_thickness_mm >= paintcore::kMinVarnishMm &&
          edit.varnish_thickness_mm <= paintcore::kMaxVarnishMm))
      throw std::runtime_error("--varnish-thickness " +
                               util::number_text(edit.varnish_thickness_mm) + ": must be in [" +
                               util::number_text(paintcore::kMinVarnishMm) + ", " +
                               util::number_text(paintcore::kMaxVarnishMm) + "] mm");
    painting.apply_varnish(*edit.varnish, edit.varnish_thickness_mm, cells);
    char text[160];
    std::snprintf(text, sizeof text,
                  "%.3g mm of %s varnish over %dx%d cells (wet: it dries with "
                  "the paint)",
                  edit.varnish_thickness_mm,
                  std::string(paintcore::finish_name(*edit.varnish)).c_str(), cells.x1 - cells.x0,
                  cells.y1 - cells.y0);
    result.varnished = text;
  }
  if (edit.dry) {
    if (!(*edit.dry >= 0.0 && *edit.dry <= 1.0))
      throw std::runtime_error("--dry " + std::to_string(*edit.dry) + ": must be in [0, 1]");
    painting.dry(*edit.dry);
    result.dried = *edit.dry;
  }
  result.reframed = edit.crop.has_value() || edit.size.has_value();
  return result;
}

std::string CanvasEditResult::summary(const paintcore::Painting& painting) const {
  char text[160];
  std::snprintf(text, sizeof text, "canvas %dx%d -> %dx%d cells; paint cut away: %.4g mm^3",
                old_width, old_height, width, height, cut.volume);
  std::string out = reframed ? text : "";
  std::string parts;
  for (std::size_t s = 0; s < cut.pigment.size() && s < painting.pigment_slots().size(); ++s) {
    if (cut.pigment[s] <= 0.0) continue;
    std::snprintf(text, sizeof text, "%s%s %.4g", parts.empty() ? "" : ", ",
                  painting.pigment_slots()[s].c_str(), cut.pigment[s]);
    parts += text;
  }
  if (!parts.empty()) out += " (" + parts + ")";
  const auto add = [&out](const std::string& part) { out += (out.empty() ? "" : "; ") + part; };
  if (!varnished.empty()) add(varnished);
  if (dried) {
    std::snprintf(text, sizeof text, "dried by %.3g", *dried);
    add(text);
  }
  return out;
}

namespace {

// The solid once, coloured by the render only when a file takes colours.
void write_solids(const paintcore::Painting& painting, const render::HeightGrid& heights,
                  const ExportRequest& request, ExportReport& report) {
  render::SolidMesh mesh = render::relief_solid(heights, request.solid);
  const bool coloured = std::any_of(request.solids.begin(), request.solids.end(), [](auto& path) {
    return util::ascii_lowercase(path.extension().string()) != ".stl";
  });
  if (coloured) {
    render::check_render_memory(painting.canvas(), request.solids.front().string());
    render::colour_solid(mesh, render::render_painting(painting, request.settings),
                         heights.cell_mm);
  }
  for (const std::filesystem::path& path : request.solids) render::write_solid(path, mesh);
  report.solid_triangles = mesh.triangles.size();
  report.solid_vertices = mesh.vertices.size();
  report.solid_error_mm = mesh.max_error_mm;
}

}  // namespace

ExportReport export_painting(const paintcore::Painting& painting, const ExportRequest& request) {
  ExportReport report;
  if (request.image.empty() && request.height_map.empty() && request.normal_map.empty() &&
      request.solids.empty())
    throw std::runtime_error(
        "export: nothing to write (give -o, --height-map, --normal-map, --stl, --ply or --obj)");
  // Two outputs into one file would leave only the last: refuse before writing either.
  std::vector<std::pair<const char*, const std::filesystem::path*>> outputs = {
      {"-o", &request.image},
      {"--height-map", &request.height_map},
      {"--normal-map", &request.normal_map}};
  for (const std::filesystem::path& solid : request.solids) outputs.push_back({"a solid", &solid});
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      const std::filesystem::path &a = *outputs[i].second, &b = *outputs[j].second;
      std::error_code error;
      if (!a.empty() && !b.empty() &&
          (std::filesystem::weakly_canonical(a, error) ==
           std::filesystem::weakly_canonical(b, error)))
        throw std::runtime_error(std::string("export: ") + outputs[i].first + " and " +
                                 outputs[j].first + " name the same file, " + a.string());
    }
  const bool relief_outputs =
      !request.height_map.empty() || !request.normal_map.empty() || !request.solids.empty();
  // The maps and solids need the whole finer painting: refined once, the image rendered from it
  // too. The image alone is refined a band at a time where it can be (render_painting_to_file).
  std::optional<paintcore::Painting> refined;
  if (request.scale != 1 && relief_outputs) refined.emplace(painting.refined(request.scale));
  const paintcore::Painting& source = refined ? *refined : painting;
  const int image_scale = refined ? 1 : request.scale;
  if (!request.image.empty()) {
    render::check_render_to_file_memory(source, request.settings, request.image,
                                        request.supersample, request.image.string(), image_scale);
    render::render_painting_to_file(source, request.settings, request.image, {},
                                    request.supersample, image_scale);
  }
  if (relief_outputs) {
    const render::HeightGrid heights = render::surface_heights(source.canvas());
    if (!request.height_map.empty()) render::write_height_map(request.height_map, heights);
    if (!request.normal_map.empty()) render::write_normal_map(request.normal_map, heights);
    if (!request.solids.empty()) write_solids(source, heights, request, report);
  }
  return report;
}

}  // namespace impasto::session
