#pragma once
// How the paint's surface reflects and how far light spreads inside it (docs/surface.md):
// the render settings' `surface` group, with its spellings and checks.
#include <optional>
#include <string_view>

#include "impasto/render/surface_brdf.hpp"
#include "impasto/util/enum_names.hpp"

namespace impasto::render {

// blinn: the Blinn-Phong terms of RenderSettings::dry_material and wet_material on the K-M
// colour (the fast choice, and the default: it renders as before bit for bit). ghs: the
// rough dielectric surface per wavelength node (surface_brdf.hpp) over the K-M body, which
// gets only the light the surface lets through, and the subsurface spread.
enum class SurfaceModel { blinn, ghs };
inline constexpr util::EnumNames<SurfaceModel, 2> kSurfaceModelNames{
    {{SurfaceModel::blinn, "blinn"}, {SurfaceModel::ghs, "ghs"}}};

struct SurfaceSettings {
  SurfaceModel model = SurfaceModel::blinn;
  // The medium the paint was mixed with: the finish of its dried surface (wet paint is a
  // liquid and always glossy).
  surface::Finish medium = surface::Finish::gloss;
  // How much of the paint is that medium, 0..1: 0 is paint straight from the tube (it dries
  // satin), 1 the medium's own finish; between, the roughness is interpolated geometrically.
  double medium_amount = 1.0;
  // A varnish over the whole painting, dried: its surface replaces the paint's (the paint
  // and a resin varnish nearly match in index, so the buried rough surface scatters little).
  std::optional<surface::Finish> varnish;
  double binder_index = 1.48;   // n_d of the paint's binder (linseed oil)
  double varnish_index = 1.53;  // n_d of a resin varnish (dammar, MS2A)
  // RMS slope (radians, per axis) of the relief finer than a cell: a cell's one normal stands
  // for a patch whose own normals spread by the curvature of the ridges and furrows it lies on
  // and by bristle marks under the 0.1 mm grid; on brushed heavy paint about 0.1 (measured in
  // docs/surface.md, "Glints"). Smaller, a glint lights only the odd cell whose normal meets
  // the half vector.
  double subcell_slope_rms = 0.1;
  // Off: the K-M body alone, without the light the surface reflects (the subsurface pass
  // renders the two apart; tests).
  bool reflection = true;
  // ghs: spread the body's light sideways where the top layer's diffusion length exceeds
  // subsurface_min_cells of a cell (subsurface.hpp); elsewhere nothing is done.
  bool subsurface = true;
  double subsurface_min_cells = 0.25;
};

// Throws std::runtime_error naming the first field out of range.
void validate(const SurfaceSettings& settings);

SurfaceModel parse_surface_model(std::string_view text);  // kSurfaceModelNames
surface::Finish parse_finish(std::string_view text);      // surface::kFinishNames
// "none" or a finish.
std::optional<surface::Finish> parse_varnish(std::string_view text);

}  // namespace impasto::render
