#pragma once
// The command line's surface options (docs/surface.md), shared by the commands that render:
// --surface blinn|ghs, --medium, --varnish, --no-subsurface, --subsurface-map FILE.png.
#include <CLI/CLI.hpp>
#include <string>

#include <impasto/paintcore/painting.hpp>
#include <impasto/render/render_settings.hpp>

namespace impasto::app {

struct SurfaceArgs {
  std::string model{util::name_of(render::kSurfaceModelNames, render::SurfaceSettings{}.model)};
  std::string medium{
      util::name_of(render::surface::kFinishNames, render::SurfaceSettings{}.medium)};
  double medium_amount = render::SurfaceSettings{}.medium_amount;
  std::string varnish = "none";
  bool no_subsurface = false;
  std::string subsurface_map;  // the debug view, FILE.png; empty: none
};

// `with_subsurface_map`: --subsurface-map too (a command that writes one image; a video has no
// use for it).
void add_surface_options(CLI::App& command, SurfaceArgs& args, bool with_subsurface_map = true);
// Writes the parsed choices into settings.surface (the CPU and the GL paths alike: both
// render the ghs surface with its subsurface spread).
void apply_surface_options(const SurfaceArgs& args, render::RenderSettings& settings);
// When --subsurface-map was given: the map of where light spreads sideways, as a PNG.
void write_subsurface_map_if_asked(const SurfaceArgs& args, const paintcore::Painting& painting,
                                   const render::RenderSettings& settings);

}  // namespace impasto::app
