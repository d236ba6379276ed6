// impasto bench surface: what the surface models cost per cell and how far they are from
// brute-force references (docs/surface.md): the GHS scatter kernel against a Monte Carlo of
// wave optics on random rough surfaces, the dipole's sideways spread against a random walk
// of light in a paint layer, and ΔE00 of flat swatches under a raking light.
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/render/kubelka_munk_cell.hpp>
#include <impasto/render/subsurface.hpp>
#include <impasto/render/surface_reference.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "vocabulary.hpp"
#include "window_services.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_surface_cmd {
namespace {

using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

struct BenchSurfaceArgs {
  bool json = false;
  int realisations = 24;
  int photons = 200000;
  std::optional<CanvasSize> size;  // the test canvas; 256x256 when not given
};

// A test painting: ridged heavy paint (white, black) and a wet glaze band of crimson-blue
// thinning from 0.3 mm to nothing across the canvas, over a woven ground. Without
// `spreading`, black impasto all over: nothing spreads light.
paintcore::Canvas test_canvas(int width, int height, bool spreading = true) {
  paintcore::Canvas canvas({width, height, 254.0, 7});
  for (int ty = 0; ty < canvas.tiles_y(); ++ty) {
    for (int tx = 0; tx < canvas.tiles_x(); ++tx) {
      const int index = ty * canvas.tiles_x() + tx;
      paintcore::Tile& tile = canvas.ensure_tile(index, 3);
      for (int y = 0; y < kTileSize; ++y) {
        for (int x = 0; x < kTileSize; ++x) {
          const int gx = tx * kTileSize + x, gy = ty * kTileSize + y;
          const auto c = static_cast<std::size_t>(y * kTileSize + x);
          const float ridge = 0.25f + 0.15f * std::sin(0.4f * static_cast<float>(gy));
          if (gy < height / 3 && spreading) {  // white impasto
            tile.wet_volume_mm[c] = ridge;
            tile.pigment(0)[c] = ridge;
          } else if (gy < 2 * height / 3 || !spreading) {  // black impasto
            tile.wet_volume_mm[c] = ridge;
            tile.pigment(1)[c] = ridge;
          } else {  // a glaze thinning to the right
            const float glaze = 0.3f * (1.0f - static_cast<float>(gx) / static_cast<float>(width));
            tile.wet_volume_mm[c] = glaze;
            tile.pigment(2)[c] = 0.05f * glaze;
          }
        }
      }
    }
  }
  return canvas;
}

SpectralPalette palette_for(const RenderSettings& settings) {
  const auto& db = data::PigmentDatabase::defaults();
  std::vector<data::Pigment> pigments{db.get("White"), db.get("Black"), db.get("Magenta")};
  return SpectralPalette(settings, data::light_from_spec(settings.light), pigments,
                         hiding_reflectance(pigments[0]));
}

// Best of three: ns per cell of a full render (the machine may be busy).
double render_ns_per_cell(const RenderSettings& settings, const paintcore::Canvas& canvas,
                          bool with_subsurface) {
  const SpectralPalette palette = palette_for(settings);
  double best = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 3; ++trial) {
    const auto start = std::chrono::steady_clock::now();
    if (with_subsurface) {
      render_canvas_with_subsurface(canvas, palette, settings);
    } else {
      TileRenderer renderer(settings, palette);
      renderer.render_all(canvas);
    }
    const double ns =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, ns);
  }
  return best / (static_cast<double>(canvas.width_cells()) * canvas.height_cells());
}

// CIEDE2000 between two neutral greys of luminance Y (white Y = 1): only ΔL' counts.
double delta_e00_grey(double y1, double y2) {
  const auto lightness = [](double y) {
    return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : 24389.0 / 27.0 * y;
  };
  const double l1 = lightness(y1), l2 = lightness(y2);
  const double mean = 0.5 * (l1 + l2) - 50.0;
  const double s_l = 1.0 + 0.015 * mean * mean / std::sqrt(20.0 + mean * mean);
  return std::abs(l1 - l2) / s_l;
}

void run(const BenchSurfaceArgs& args) {
  nlohmann::json out;
  // --- 1. cost per cell ---
  const CanvasSize size = args.size.value_or(CanvasSize{256, 256});
  const paintcore::Canvas canvas = test_canvas(size.width, size.height);
  RenderSettings blinn;
  RenderSettings ghs = blinn;
  ghs.surface.model = SurfaceModel::ghs;
  ghs.surface.subsurface = false;
  RenderSettings ghs_sub = ghs;
  ghs_sub.surface.subsurface = true;
  const SpectralPalette palette = palette_for(ghs_sub);
  const std::size_t spreading = subsurface_map(canvas, palette, ghs_sub).cells.size();
  const double ns_blinn = render_ns_per_cell(blinn, canvas, false);
  const double ns_ghs = render_ns_per_cell(ghs, canvas, false);
  const double ns_sub = render_ns_per_cell(ghs_sub, canvas, true);
  out["cost"] = {{"canvas_cells", size.width * size.height},
                 {"spreading_cells", spreading},
                 {"blinn_ns_per_cell", ns_blinn},
                 {"ghs_ns_per_cell", ns_ghs},
                 {"ghs_subsurface_ns_per_cell", ns_sub}};
  if (!args.json) {
    std::printf("cost per cell, %dx%d test canvas, 8 nodes (best of 3):\n", size.width,
                size.height);
    std::printf("  blinn                 %8.0f ns\n", ns_blinn);
    std::printf("  ghs surface           %8.0f ns  (+%.0f)\n", ns_ghs, ns_ghs - ns_blinn);
    std::printf("  ghs + subsurface      %8.0f ns  (+%.0f; %zu of %d cells spread)\n", ns_sub,
                ns_sub - ns_ghs, spreading, size.width * size.height);
  }
  // The same on the GPU (upload and one draw; llvmpipe where there is no GPU), and on black
  // impasto all over, where nothing spreads.
  if (const WindowServices* services = window_services(); services && services->spread_cost) {
    const std::optional<GpuSpreadCost> gpu =
        services->spread_cost(canvas, test_canvas(size.width, size.height, false), ghs, palette);
    out["gpu_cost"] = {{"spreading_cells", gpu->spreading_cells},
                       {"ghs_ns_per_cell", gpu->spreading_off},
                       {"ghs_subsurface_ns_per_cell", gpu->spreading_on},
                       {"nothing_spreads_ghs_ns_per_cell", gpu->plain_off},
                       {"nothing_spreads_ghs_subsurface_ns_per_cell", gpu->plain_on}};
    if (!args.json) {
      std::printf("  GPU ghs               %8.0f ns\n", gpu->spreading_off);
      std::printf("  GPU ghs + subsurface  %8.0f ns  (+%.0f; %d cells spread)\n", gpu->spreading_on,
                  gpu->spreading_on - gpu->spreading_off, gpu->spreading_cells);
      std::printf("  GPU, nothing spreads  %8.0f ns  off, %.0f on (+%.0f)\n", gpu->plain_off,
                  gpu->plain_on, gpu->plain_on - gpu->plain_off);
    }
  }

  // --- 2. the GHS kernel against wave optics by Monte Carlo ---
  if (!args.json) {
    std::printf(
        "\nGHS kernel vs wave-optics Monte Carlo (%d surfaces each), light at 20 deg, viewer "
        "above:\n  finish  nm   in 1 deg: ghs  mc    beyond 5 deg: ghs  mc    "
        "flat-swatch dE00 black  white\n",
        args.realisations);
  }
  const double elevation = 20.0 * std::numbers::pi / 180.0;
  const double mu_i = std::sin(elevation);
  const double gamma_sum = mu_i + 1.0;
  const double rho_view = std::cos(elevation);  // the viewer's distance from the mirror
  // Body luminances of opaque black and white (K-M, the palette's own).
  const auto body_y = [&](int slot) {
    const float* k = palette.absorption(slot);
    const float* s = palette.scattering(slot);
    std::vector<float> r(static_cast<std::size_t>(palette.nodes()));
    for (int i = 0; i < palette.nodes(); ++i) {
      r[static_cast<std::size_t>(i)] = km::reflectance_infinite(k[i], s[i]);
    }
    double y = 0.0;
    for (int i = 0; i < palette.nodes(); ++i)
      y += palette.to_display_xyz(1)[i] * r[static_cast<std::size_t>(i)];
    return y;
  };
  const double y_black = body_y(1), y_white = body_y(0);
  nlohmann::json kernels = nlohmann::json::array();
  for (surface::Finish finish :
       {surface::Finish::gloss, surface::Finish::satin, surface::Finish::matte}) {
    for (double nm : {450.0, 600.0}) {
      surface::GhsParams p;
      p.roughness = surface::finish_roughness(finish);
      p.wavelength_nm = nm;
      p.index = surface::binder_index(nm);
      p.source_sigma = 0.25 * 3.0 * std::numbers::pi / 180.0;
      const auto mc = surface_reference::wave_optics_kernel(p, gamma_sum, args.realisations, 11);
      // Shares of the lobe within 1° and beyond 5° of the mirror (≈ ρ 0.0175, 0.087).
      double ghs_in = 0, mc_in = 0, ghs_out = 0, mc_out = 0, ghs_total = 0, mc_total = 0;
      for (std::size_t b = 0; b < mc.kernel.size(); ++b) {
        const double rho = (b + 0.5) * mc.rho_step;
        const double area = 2.0 * std::numbers::pi * rho * mc.rho_step;
        const double g = surface::ghs_kernel(p, gamma_sum / 2, gamma_sum / 2, rho) * area;
        const double m = mc.kernel[b] * area;
        ghs_total += g;
        mc_total += m;
        if (rho < 0.0175) {
          ghs_in += g;
          mc_in += m;
        }
        if (rho > 0.087) {
          ghs_out += g;
          mc_out += m;
        }
      }
      // The flat swatch under the raking light: body + π F K μ_i / μ_i (flat) at the viewer.
      const std::size_t view_bin = static_cast<std::size_t>(rho_view / mc.rho_step);
      const double cos_half = std::sqrt(0.5 * (1.0 + mu_i));
      const double fresnel = surface::fresnel_dielectric(cos_half, p.index);
      const double spec_ghs = std::numbers::pi * fresnel *
                              surface::ghs_kernel(p, gamma_sum / 2, gamma_sum / 2, rho_view);
      const double spec_mc =
          std::numbers::pi * fresnel * (view_bin < mc.kernel.size() ? mc.kernel[view_bin] : 0.0);
      const double de_black = delta_e00_grey(y_black + spec_ghs, y_black + spec_mc);
      const double de_white = delta_e00_grey(y_white + spec_ghs, y_white + spec_mc);
      const std::string name{util::name_of(surface::kFinishNames, finish)};
      kernels.push_back({{"finish", name},
                         {"wavelength_nm", nm},
                         {"within_1deg", {ghs_in, mc_in}},
                         {"beyond_5deg", {ghs_out, mc_out}},
                         {"total", {ghs_total, mc_total}},
                         {"delta_e00_black", de_black},
                         {"delta_e00_white", de_white}});
      if (!args.json) {
        std::printf(
            "  %-6s %4.0f        %.3f %.3f             %.3f %.3f                %.2f   %.2f\n",
            name.c_str(), nm, ghs_in, mc_in, ghs_out, mc_out, de_black, de_white);
      }
    }
  }
  out["kernel"] = kernels;

  // --- 3. the spread against a random walk in a layer over a white ground ---
  if (!args.json) {
    std::printf(
        "\nsideways spread vs random walk in the layer (%d photons), share of the light leaving "
        "beyond the entry cell (0.1 mm cells):\n  layer                      thickness  "
        "spread length  model   walk    walk R\n",
        args.photons);
  }
  nlohmann::json spreads = nlohmann::json::array();
  const double cell_mm = 0.1;
  struct Layer {
    const char* name;
    double k, s;  // K-M per unit thickness at 550 nm (representative)
  };
  for (const Layer& layer :
       {Layer{"glaze (K 0.02, S 0.005)", 0.02, 0.005}, Layer{"thin white (K 0.01, S 1)", 0.01, 1.0},
        Layer{"tint (K 0.2, S 0.5)", 0.2, 0.5}}) {
    for (double thickness : {0.02, 0.1, 0.3}) {
      const dipole::Medium medium = dipole::from_kubelka_munk(layer.k, layer.s, 0.005);
      const double length = spread_length_mm(medium, thickness);
      const SpreadKernel kernel = spread_kernel(medium, thickness, cell_mm);
      const double model = 1.0 - kernel.at(0, 0);
      const auto walk = surface_reference::random_walk_layer(
          medium, thickness, 0.9, cell_mm / std::sqrt(std::numbers::pi), args.photons, 5);
      spreads.push_back({{"layer", layer.name},
                         {"thickness_mm", thickness},
                         {"spread_length_cells", length / cell_mm},
                         {"model_beyond", model},
                         {"walk_beyond", walk.beyond_share},
                         {"walk_reflectance", walk.reflectance}});
      if (!args.json) {
        std::printf("  %-26s %6.2f mm  %8.2f cells  %.3f   %.3f   %.3f\n", layer.name, thickness,
                    length / cell_mm, model, walk.beyond_share, walk.reflectance);
      }
    }
  }
  out["spread"] = spreads;
  if (args.json) std::printf("%s\n", out.dump(2).c_str());
}

const CommandRegistrar registrar("bench surface", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "surface",
      "Cost per cell of the surface models and their error against brute-force references "
      "(docs/surface.md)");
  auto args = std::make_shared<BenchSurfaceArgs>();
  add_json_flag(*cmd, args->json, "the costs, the kernel shares and the spread shares");
  cmd->add_option("--realisations", args->realisations, "Random surfaces per kernel reference")
      ->check(finite_range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--photons", args->photons, "Photons per random walk")
      ->check(finite_range(100, 100000000))
      ->capture_default_str();
  add_size_option(*cmd, args->size, "the synthetic test canvas of the cost (256x256)");
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_surface_cmd
