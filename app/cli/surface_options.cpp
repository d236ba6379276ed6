#include "surface_options.hpp"

#include <impasto/render/image.hpp>
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render/subsurface.hpp>
#include <iostream>
#include <stdexcept>

#include "vocabulary.hpp"

namespace impasto::app {

void add_surface_options(CLI::App& command, SurfaceArgs& args, bool with_subsurface_map) {
  command
      .add_option("--surface", args.model,
                  "Surface reflection: blinn (Blinn-Phong, fast) or ghs (rough dielectric per "
                  "wavelength, with subsurface spread; docs/surface.md)")
      ->check(CLI::IsMember(util::names_of(render::kSurfaceModelNames)))
      ->capture_default_str();
  command.add_option("--medium", args.medium, "ghs: the paint's medium, the finish it dries to")
      ->check(CLI::IsMember(util::names_of(render::surface::kFinishNames)))
      ->capture_default_str();
  command
      .add_option("--medium-amount", args.medium_amount,
                  "ghs: share of medium in the paint, 0 (tube paint, dries satin) to 1 (the "
                  "medium's finish)")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  std::vector<std::string> varnishes{"none"};
  for (const auto& name : util::names_of(render::surface::kFinishNames)) varnishes.push_back(name);
  command.add_option("--varnish", args.varnish, "ghs: a varnish over the whole painting")
      ->check(CLI::IsMember(varnishes))
      ->capture_default_str();
  command.add_flag("--no-subsurface", args.no_subsurface,
                   "ghs: no sideways spread of light inside the paint");
  if (!with_subsurface_map) return;
  command.add_option("--subsurface-map", args.subsurface_map,
                     "ghs: also write where light spreads sideways (per channel, 4 cells = full "
                     "scale) to this PNG");
}

void apply_surface_options(const SurfaceArgs& args, render::RenderSettings& settings) {
  settings.surface.model = render::parse_surface_model(args.model);
  settings.surface.medium = render::parse_finish(args.medium);
  settings.surface.medium_amount = args.medium_amount;
  settings.surface.varnish = render::parse_varnish(args.varnish);
  settings.surface.subsurface = !args.no_subsurface;
  if (!args.subsurface_map.empty() && settings.surface.model != render::SurfaceModel::ghs) {
    throw std::runtime_error(
        "--subsurface-map: only the ghs surface spreads light (--surface ghs)");
  }
}

void write_subsurface_map_if_asked(const SurfaceArgs& args, const paintcore::Painting& painting,
                                   const render::RenderSettings& settings) {
  if (args.subsurface_map.empty()) return;
  const render::SpectralPalette palette(settings, painting);
  const render::SubsurfaceMap map = render::subsurface_map(painting.canvas(), palette, settings);
  render::write_png(args.subsurface_map, render::subsurface_map_image(map));
  std::cout << "wrote " << args.subsurface_map << " (" << map.cells.size()
            << " cells spread light sideways)\n";
}

}  // namespace impasto::app
