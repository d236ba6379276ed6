#include "impasto/render/crack_shading.hpp"

#include <algorithm>
#include <span>

#include "impasto/cracks/cavity_correction.hpp"
#include "impasto/cracks/cavity_look.hpp"
#include "impasto/cracks/cavity_table.hpp"
#include "impasto/cracks/gouffe.hpp"

namespace impasto::render {
namespace {

// A painting's crack shape codes are the cracks library's shapes, in order.
static_assert(cracks::kAllShapes.size() == paintcore::kCrackShapeCount);

cracks::CrackCell crack_cell(const paintcore::CrackRecord& r) {
  // The record's shape code was checked when it entered the painting (validate_cracks).
  return {r.depth_mm, r.half_width_mm, static_cast<cracks::CavityShape>(r.shape), r.exposed_layer};
}

// The far view's light: the sun's zenith from the light's elevation, and the sky's share
// (all of it under a diffuse, overcast light).
cracks::CrackSceneLight crack_scene_light(const RenderSettings& settings) {
  return {90.0 - std::clamp(settings.light_elevation_deg, 0.0, 90.0), crack_sky_share(settings),
          true};
}

}  // namespace

double crack_sky_share(const RenderSettings& settings) {
  return settings.light_type == LightType::diffuse ? 1.0 : std::clamp(settings.ambient, 0.0, 1.0);
}

CrackOptics crack_optics(const paintcore::CrackRecord& record, double cell_mm) {
  if (!record.has_crack()) return {};
  const cracks::CrackCell cell = crack_cell(record);
  const cracks::ViewFactors vf = cracks::view_factors(cell.shape, cell.dims());
  const cracks::CavityTable& table = cracks::shipped_cavity_table();
  // Beyond the last row only "beyond" matters (the shader scales by F and G), so the
  // coordinate is clamped to keep it small enough to pack.
  const double u =
      std::clamp(table.ratio_coordinate(static_cast<double>(cell.depth_mm) / cell.half_width_mm),
                 -1.0, static_cast<double>(table.grid().ratio_count));
  return {static_cast<float>(cracks::crack_coverage(cell, cell_mm)),
          static_cast<float>(vf.F),
          static_cast<float>(vf.G),
          record.exposed_layer == paintcore::kCrackExposesGround,
          static_cast<int>(cell.shape),
          static_cast<float>(u)};
}

std::array<double, 2> crack_table_data_light(const RenderSettings& settings) {
  const cracks::CrackSceneLight light = crack_scene_light(settings);
  return {light.sun_zenith_deg, light.sky_share};
}

CrackTableData crack_table_data(const RenderSettings& settings) {
  const cracks::CrackSceneLight light = crack_scene_light(settings);
  const auto correction = cracks::cavity_correction(light);
  const cracks::CavityTable& axial = cracks::shipped_cavity_table();
  CrackTableData d;
  d.ratio_count = correction->grid().ratio_count;
  d.rho0_count = correction->grid().rho0_count;
  d.differences = correction->differences();
  d.sun_zenith_deg = light.sun_zenith_deg;
  d.sky_share = light.sky_share;
  for (cracks::CavityShape shape : cracks::kAllShapes) {
    const cracks::ViewFactors vf =
        cracks::view_factors(shape, {axial.ratio(d.ratio_count - 1), 1.0});
    d.last_F[static_cast<std::size_t>(shape)] = static_cast<float>(vf.F);
    d.last_G[static_cast<std::size_t>(shape)] = static_cast<float>(vf.G);
  }
  return d;
}

CrackTileShading::CrackTileShading(const paintcore::Canvas& canvas, int tile_index,
                                   const RenderSettings& settings, const float* ground, int nodes)
    : tile_(settings.cracks ? canvas.cracks().tile(tile_index) : nullptr),
      cell_mm_(canvas.cell_mm()),
      correction_(settings.cracks && settings.crack_model == CrackModel::Corrected
                      ? cracks::cavity_correction(crack_scene_light(settings))
                      : nullptr),
      ground_(ground),
      nodes_(nodes) {
  if (tile_ != nullptr) walls_.resize(static_cast<std::size_t>(nodes));
}

bool CrackTileShading::take_walls(int cell, const float* dry_stack) {
  record_ = &tile_->cells[static_cast<std::size_t>(cell)];
  if (!record_->has_crack()) return false;
  // A crack through the film shows the ground; one ending inside it, the paint around it
  // (the cell's dry stack, the reflectance the renderer has baked).
  const float* walls =
      record_->exposed_layer == paintcore::kCrackExposesGround ? ground_ : dry_stack;
  std::copy_n(walls, nodes_, walls_.begin());
  return true;
}

void CrackTileShading::blend(float* reflectance) const {
  const std::span<float> out(reflectance, static_cast<std::size_t>(nodes_));
  cracks::crack_cell_reflectance(crack_cell(*record_), cell_mm_, out, walls_, out,
                                 correction_.get());
}

}  // namespace impasto::render
