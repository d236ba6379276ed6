// The ghs surface model's GLSL port (surface_ghs_lib.glsl) against the CPU reference: the GHS
// kernel on both sides of its Poisson/Gauss–Hermite switch against surface::ghs_kernel, and
// the whole canvas pass against render::TileRenderer pixel by pixel for the three finishes,
// a varnish, and a raking light, with wet paint blending toward the wet gloss.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "image_difference.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/render/surface_brdf.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/ghs_surface_tables.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"
#include "impasto/render_gl/shader_library.hpp"

namespace impasto::render_gl {
namespace {

using paintcore::kTileCells;
using paintcore::kTileSize;
namespace surface = render::surface;

constexpr int kGhsGridSide = 32;  // a 32x32 grid of kernel cases, one per pixel

// Row y: a surface and an incidence; column x: the distance from the mirror and the view.
// The roughnesses span gloss to matte, with two between whose phase variance g crosses 25
// (the switch to the Gauss–Hermite sum) as the cosines change.
surface::Roughness roughness_of(int y) {
  static const surface::Roughness kSurfaces[] = {surface::finish_roughness(surface::Finish::gloss),
                                                 surface::finish_roughness(surface::Finish::satin),
                                                 surface::finish_roughness(surface::Finish::matte),
                                                 {0.25, 3.0},
                                                 {0.35, 2.0},
                                                 {0.04, 8.0}};
  return kSurfaces[y % 6];
}
float cos_i_of(int y) {
  return 0.15f + 0.85f * static_cast<float>(y) / (kGhsGridSide - 1);
}
float cos_o_of(int x) {
  return 1.0f - 0.2f * static_cast<float>(x % 4);
}
float rho_of(int x) {
  return 0.004f * static_cast<float>(x * x) / 4.0f;
}

// GHS_TABLE_SIZE, GHS_BLOCKS, GHS_WET_BLOCK and GHS_SECOND_TABLE come from the C++
// (ghs_surface_tables.cpp), never by hand.
TEST(GhsGlsl, TableSizesAreInjectedFromTheCpp) {
  const std::string source = surface_ghs_glsl();
  EXPECT_NE(source.find("#define GHS_TABLE_SIZE " +
                        std::to_string(render::surface::GhsBrdf::kTableSize) + "\n"),
            std::string::npos);
  EXPECT_NE(source.find("#define GHS_BLOCKS " + std::to_string(GhsSurfaceTables::kBlocks) + "\n"),
            std::string::npos);
  EXPECT_NE(
      source.find("#define GHS_WET_BLOCK " + std::to_string(GhsSurfaceTables::kWetBlock) + "\n"),
      std::string::npos);
  EXPECT_NE(source.find("#define GHS_SECOND_TABLE " +
                        std::to_string(GhsSurfaceTables::kSecondTable) + "\n"),
            std::string::npos);
  std::ifstream file(std::filesystem::path(IMPASTO_SOURCE_DIR) /
                     "render/gl/shaders/surface_ghs_lib.glsl");
  std::stringstream text;
  text << file.rdbuf();
  ASSERT_FALSE(text.str().empty());
  EXPECT_EQ(text.str().find("#define GHS_"), std::string::npos);
}

TEST(GhsGlsl, KernelMatchesTheCpuReferenceOnBothSidesOfItsSwitch) {
  auto context = create_headless_context();
  const std::string source = std::string("#version 330 core\n#define MAX_NODES ") +
                             std::to_string(render::kMaxNodes) + "\n" + shading_glsl() +
                             surface_ghs_glsl() + R"glsl(
uniform vec2 roughness[32];
uniform float cos_i[32];
uniform float cos_o[32];
uniform float rho[32];
uniform float wavelength_nm;
out vec4 result;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  result = vec4(ghs_kernel(roughness[p.y], wavelength_nm, 0.013, 0.05, cos_i[p.y], cos_o[p.x],
                           rho[p.x]), 0.0, 0.0, 1.0);
})glsl";
  FullscreenPass pass("ghs_kernel_test.frag", source);
  Framebuffer target(kGhsGridSide, kGhsGridSide, TexelFormat::kRGBA32F);
  std::vector<float> roughness(2 * kGhsGridSide), cos_i(kGhsGridSide), cos_o(kGhsGridSide),
      rho(kGhsGridSide);
  for (int i = 0; i < kGhsGridSide; ++i) {
    roughness[2 * i] = static_cast<float>(roughness_of(i).rms_um);
    roughness[2 * i + 1] = static_cast<float>(roughness_of(i).correlation_um);
    cos_i[i] = cos_i_of(i);
    cos_o[i] = cos_o_of(i);
    rho[i] = rho_of(i);
  }
  int below_switch = 0, above_switch = 0;
  for (float wavelength : {420.0f, 680.0f}) {
    target.bind();
    pass.program().use();
    glUniform2fv(pass.program().uniform("roughness"), kGhsGridSide, roughness.data());
    glUniform1fv(pass.program().uniform("cos_i"), kGhsGridSide, cos_i.data());
    glUniform1fv(pass.program().uniform("cos_o"), kGhsGridSide, cos_o.data());
    glUniform1fv(pass.program().uniform("rho"), kGhsGridSide, rho.data());
    glUniform1f(pass.program().uniform("wavelength_nm"), wavelength);
    pass.draw();
    const std::vector<float> pixels = target.read_rgba_float();
    double worst = 0.0;
    for (int y = 0; y < kGhsGridSide; ++y) {
      for (int x = 0; x < kGhsGridSide; ++x) {
        surface::GhsParams p;
        p.roughness = {roughness[2 * y], roughness[2 * y + 1]};  // the floats the GPU got
        p.wavelength_nm = wavelength;
        p.source_sigma = 0.013f;
        p.subcell_slope_rms = 0.05f;
        const double cpu = surface::ghs_kernel(p, cos_i[y], cos_o[x], rho[x]);
        const double gpu = pixels[static_cast<std::size_t>(4 * (y * kGhsGridSide + x))];
        const double g = std::pow(2.0 * std::numbers::pi * p.roughness.rms_um /
                                      (wavelength * 1e-3) * (cos_i[y] + cos_o[x]),
                                  2.0);
        (g > 25.0 ? above_switch : below_switch)++;
        // Float against double: exp of arguments up to ~50 keeps ~1e-4 of relative error.
        EXPECT_NEAR(gpu, cpu, 1e-3 * cpu + 1e-6)
            << "rms " << p.roughness.rms_um << " cos " << cos_i[y] << "," << cos_o[x] << " rho "
            << rho[x] << " g " << g;
        worst = std::max(worst, std::abs(gpu - cpu) / (cpu + 1e-6));
      }
    }
    RecordProperty("worst_relative_" + std::to_string(static_cast<int>(wavelength)),
                   std::to_string(worst));
  }
  // Both branches of the sum were exercised.
  EXPECT_GT(below_switch, 100);
  EXPECT_GT(above_switch, 100);
}

// 150x100 cells: a dry layer with brush ridges (slopes that turn highlights toward the
// viewer) under a blob of wet paint thinning to nothing at its edge (wetness from full to
// none), black on the left where the surface light shows most, one tile untouched.
paintcore::Canvas make_ridged_canvas() {
  paintcore::Canvas canvas({150, 100, 300.0, 7});
  const int slots = static_cast<int>(test::kWhiteBlueRedBlack.size());
  paintcore::DryLayer layer;
  for (int index : {0, 1, 4}) {
    paintcore::Tile& tile = canvas.ensure_tile(index, slots);
    paintcore::DryTile dry;
    dry.tile_index = index;
    dry.volume_mm.assign(kTileCells, 0.0f);
    dry.slots = {0, 3};
    dry.pigment_mm.assign(2 * kTileCells, 0.0f);
    const int x0 = (index % canvas.tiles_x()) * kTileSize;
    const int y0 = (index / canvas.tiles_x()) * kTileSize;
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int gx = x0 + cell % kTileSize, gy = y0 + cell / kTileSize;
      const float ridge = 0.15f + 0.1f * static_cast<float>(std::sin(gx * 0.45 + gy * 0.12));
      dry.volume_mm[cell] = ridge;
      tile.dry_height_mm[cell] = ridge;
      const bool black = gx < 50;
      dry.pigment_mm[static_cast<std::size_t>(black ? kTileCells + cell : cell)] = ridge * 0.5f;
      const double r = std::hypot(gx - 80.0, gy - 45.0);
      const float wet = r < 35.0 ? static_cast<float>(0.25 * (1.0 - r / 35.0)) : 0.0f;
      if (wet <= 0.0f || gx >= canvas.width_cells() || gy >= canvas.height_cells()) continue;
      tile.wet_volume_mm[cell] = wet;
      tile.pigment(1)[cell] = 0.4f * wet;
      tile.pigment(2)[cell] = 0.3f * wet;
      tile.pigment(0)[cell] = 0.3f * wet;
    }
    layer.tiles.push_back(std::move(dry));
  }
  canvas.dry_layers().push_back(std::move(layer));
  return canvas;
}

struct FinishCase {
  std::string name;
  surface::Finish medium;
  std::optional<surface::Finish> varnish;
  double elevation_deg;
};

void PrintTo(const FinishCase& c, std::ostream* os) {
  *os << c.name;
}

class GhsCanvas : public ::testing::TestWithParam<FinishCase> {};

// Half a level of 255 in the display encoding, a quarter of the other image tests' two levels
// (canvas_image_test.cpp): the GPU evaluates in float what the CPU does partly in double (the
// kernel and the tables' interpolation), ~1e-4 relative at worst (GhsGlsl above); measured
// 0.02/255 on llvmpipe. A highlight of 1.0 off by 1e-4 is 0.03/255 there.
TEST_P(GhsCanvas, GpuMatchesCpuWithinHalfALevelOf255) {
  const FinishCase& c = GetParam();
  render::RenderSettings settings;
  settings.surface.model = render::SurfaceModel::ghs;
  settings.surface.medium = c.medium;
  settings.surface.varnish = c.varnish;
  settings.surface.subsurface = false;  // not in TileRenderer (subsurface_spread_test.cpp)
  settings.light_elevation_deg = c.elevation_deg;
  settings.light_azimuth_deg = 200.0;
  const paintcore::Canvas canvas = make_ridged_canvas();

  render::TileRenderer cpu(settings, test::kWhiteBlueRedBlack);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  const render::Image actual = render_painting_gpu(canvas, test::kWhiteBlueRedBlack, settings);
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const auto [worst, mean, worst_x, worst_y] = test::compare_images(actual, expected);
  std::cout << "[ " << c.name << " ] GPU vs CPU: max " << worst * 255 << "/255 at (" << worst_x
            << "," << worst_y << "), mean " << mean * 255 << "/255\n";
  RecordProperty("max_difference_255", std::to_string(worst * 255));
  EXPECT_LE(worst, 0.5 / 255.0) << "worst pixel (" << worst_x << "," << worst_y << ")";

  // Not vacuous: the same canvas under Blinn-Phong differs (the ghs terms were drawn).
  render::RenderSettings blinn = settings;
  blinn.surface.model = render::SurfaceModel::blinn;
  const render::Image blinn_image = render_painting_gpu(canvas, test::kWhiteBlueRedBlack, blinn);
  double changed = 0.0;
  for (std::size_t i = 0; i < blinn_image.rgb.size(); ++i)
    changed = std::max(changed, std::abs(double(blinn_image.rgb[i]) - actual.rgb[i]));
  EXPECT_GT(changed, 10.0 / 255.0);
}

INSTANTIATE_TEST_SUITE_P(
    Finishes, GhsCanvas,
    ::testing::Values(FinishCase{"gloss", surface::Finish::gloss, std::nullopt, 50.0},
                      FinishCase{"satin", surface::Finish::satin, std::nullopt, 50.0},
                      FinishCase{"matte", surface::Finish::matte, std::nullopt, 50.0},
                      FinishCase{"matte_raking", surface::Finish::matte, std::nullopt, 15.0},
                      FinishCase{"matte_varnished_gloss", surface::Finish::matte,
                                 surface::Finish::gloss, 30.0}),
    [](const ::testing::TestParamInfo<FinishCase>& info) { return info.param.name; });

// The window's path: a surface chosen after the renderer was made (set_settings) and the
// light dragged after that (set_shading) follow the CPU as a new renderer would.
TEST(GhsCanvasSettings, SetSettingsAndTheLightSwitchTheModelBothWays) {
  auto context = create_headless_context();
  const paintcore::Canvas canvas = make_ridged_canvas();
  render::RenderSettings settings;
  settings.surface.subsurface = false;
  CanvasRenderer gpu(canvas.width_cells(), canvas.height_cells(), settings,
                     render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  Framebuffer target(canvas.width_cells(), canvas.height_cells(), TexelFormat::kRGBA32F);
  const auto draw_against_cpu = [&](const render::RenderSettings& s, const char* step) {
    gpu.upload_all(canvas);
    target.bind();
    gpu.draw(one_pixel_per_cell(canvas.width_cells(), canvas.height_cells()), canvas.width_cells(),
             canvas.height_cells());
    const std::vector<float> rgba = target.read_rgba_float();
    render::TileRenderer cpu(s, test::kWhiteBlueRedBlack);
    cpu.render_all(canvas);
    const render::Image expected = cpu.image();
    double worst = 0.0;
    for (int y = 0; y < expected.height; ++y) {
      for (int x = 0; x < expected.width; ++x) {
        const float* p =
            &rgba[static_cast<std::size_t>(((expected.height - 1 - y) * expected.width + x) * 4)];
        for (int ch = 0; ch < 3; ++ch)
          worst = std::max(worst, std::abs(double(p[ch]) - expected.pixel(x, y)[ch]));
      }
    }
    EXPECT_LE(worst, 0.5 / 255.0) << step;
  };
  settings.surface.model = render::SurfaceModel::ghs;
  settings.surface.medium = surface::Finish::matte;
  gpu.set_settings(settings, render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  draw_against_cpu(settings, "ghs matte");
  settings.light_elevation_deg = 20.0;
  gpu.set_shading(settings);
  draw_against_cpu(settings, "light lowered");
  settings.surface.model = render::SurfaceModel::blinn;
  gpu.set_settings(settings, render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  draw_against_cpu(settings, "back to blinn");
}

// The painting's own media and varnish (paintcore::cell_surface): bands of a gloss medium, a
// matte medium at half share, a satin varnish half dry and a matte varnish dry, each cell on
// its own surface level on both sides.
TEST(GhsCanvasCells, MediaAndVarnishOfEachCellMatchTheCpu) {
  paintcore::Canvas canvas = make_ridged_canvas();
  for (int index : {0, 1, 4}) {
    paintcore::Tile& tile =
        canvas.ensure_tile(index, static_cast<int>(test::kWhiteBlueRedBlack.size()));
    tile.medium.assign(static_cast<std::size_t>(paintcore::kMediumPlanes) * kTileCells, 0.0f);
    tile.varnish.assign(static_cast<std::size_t>(paintcore::kVarnishPlanes) * kTileCells, 0.0f);
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int band = (cell / kTileSize) / 16;  // four bands of 16 rows a tile
      const auto c = static_cast<std::size_t>(cell);
      const auto log_rms = [](surface::Finish f) {
        return static_cast<float>(std::log10(surface::finish_roughness(f).rms_um));
      };
      if (band == 0) {
        tile.medium[c] = 1.0f;
        tile.medium[kTileCells + c] = log_rms(surface::Finish::gloss);
      } else if (band == 1) {
        tile.medium[c] = 0.5f;
        tile.medium[kTileCells + c] = log_rms(surface::Finish::matte);
      } else {
        tile.varnish[c] = 0.03f;
        tile.varnish[kTileCells + c] = band == 2 ? 0.015f : 0.0f;
        tile.varnish[2 * kTileCells + c] =
            log_rms(band == 2 ? surface::Finish::satin : surface::Finish::matte);
      }
    }
  }
  render::RenderSettings settings;
  settings.surface.model = render::SurfaceModel::ghs;
  settings.surface.subsurface = false;
  settings.light_elevation_deg = 25.0;
  settings.light_azimuth_deg = 200.0;
  render::TileRenderer cpu(settings, test::kWhiteBlueRedBlack);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  const render::Image actual = render_painting_gpu(canvas, test::kWhiteBlueRedBlack, settings);
  double worst = 0.0;
  for (std::size_t i = 0; i < expected.rgb.size(); ++i)
    worst = std::max(worst, std::abs(double(actual.rgb[i]) - expected.rgb[i]));
  std::cout << "[ cells ] GPU vs CPU: max " << worst * 255 << "/255\n";
  EXPECT_LE(worst, 0.5 / 255.0);
  // Not vacuous: without the cells' surfaces the CPU renders otherwise.
  paintcore::Canvas plain = make_ridged_canvas();
  render::TileRenderer cpu_plain(settings, test::kWhiteBlueRedBlack);
  cpu_plain.render_all(plain);
  const render::Image plain_image = cpu_plain.image();
  double changed = 0.0;
  for (std::size_t i = 0; i < expected.rgb.size(); ++i)
    changed = std::max(changed, std::abs(double(plain_image.rgb[i]) - expected.rgb[i]));
  EXPECT_GT(changed, 10.0 / 255.0);
}

// Zoomed in (the window's smooth zoom), a ghs pixel is the bilinear blend of the four nearest
// cells' shaded colours (the CPU image's, linear sRGB), not a block of its cell.
TEST(GhsCanvasZoom, ZoomedInPixelsBlendTheFourNearestCellsShading) {
  auto context = create_headless_context();
  const paintcore::Canvas canvas = make_ridged_canvas();
  render::RenderSettings settings;
  settings.surface.model = render::SurfaceModel::ghs;
  settings.surface.subsurface = false;
  settings.display = render::DisplayEncoding::linear_srgb;  // blending is linear on both sides
  render::TileRenderer cpu(settings, test::kWhiteBlueRedBlack);
  cpu.render_all(canvas);
  const render::Image cells = cpu.image();
  CanvasRenderer gpu(canvas.width_cells(), canvas.height_cells(), settings,
                     render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  gpu.upload_all(canvas);
  constexpr int kPixelsPerCell = 4, kSide = 64;  // around the canvas centre
  Framebuffer target(kSide, kSide, TexelFormat::kRGBA32F);
  target.bind();
  const CanvasView view{75.0, 50.0, static_cast<double>(kPixelsPerCell), 0.0};
  gpu.draw(view, kSide, kSide);
  const std::vector<float> rgba = target.read_rgba_float();
  double worst = 0.0, step = 0.0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      // The pixel's centre in cells (rows down), and its four nearest cell centres.
      const double px = 75.0 + (x + 0.5 - 0.5 * kSide) / kPixelsPerCell - 0.5;
      const double py = 50.0 + (y + 0.5 - 0.5 * kSide) / kPixelsPerCell - 0.5;
      const int cx = static_cast<int>(std::floor(px)), cy = static_cast<int>(std::floor(py));
      const double fx = px - cx, fy = py - cy;
      const float* p = &rgba[static_cast<std::size_t>(((kSide - 1 - y) * kSide + x) * 4)];
      for (int ch = 0; ch < 3; ++ch) {
        const double expected = (1 - fx) * (1 - fy) * cells.pixel(cx, cy)[ch] +
                                fx * (1 - fy) * cells.pixel(cx + 1, cy)[ch] +
                                (1 - fx) * fy * cells.pixel(cx, cy + 1)[ch] +
                                fx * fy * cells.pixel(cx + 1, cy + 1)[ch];
        worst = std::max(worst, std::abs(p[ch] - expected));
        if (x > 0) step = std::max(step, double(std::abs(p[ch] - p[ch - 4])));
      }
    }
  }
  std::cout << "[ zoom ] GPU vs bilinear CPU: max " << worst << "\n";
  EXPECT_LE(worst, 0.5 / 255.0);
  EXPECT_GT(step, 0.0);  // not flat: the view shows the canvas
}

}  // namespace
}  // namespace impasto::render_gl
