// The window target provides the command line's OpenGL and font services (window_services.hpp)
// as the program starts: a static object, kept by the object library as the commands are.
#include "window_services.hpp"

#include <imgui.h>

#include <cmath>

#include <impasto/render_gl/render_painting_gpu.hpp>

#include "bench_surface_gpu.hpp"

namespace impasto::app {
namespace {

// ImGui's built-in font (ProggyClean, 13 px), rasterised once without a UI context.
struct LabelFont {
  ImFontAtlas atlas;
  ImFont* font = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  LabelFont() {
    font = atlas.AddFontDefault();
    atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
  }
};

const ImFontGlyph* glyph(LabelFont& font, char ch) {
  return font.font->FindGlyph(static_cast<ImWchar>(static_cast<unsigned char>(ch)));
}

void text_pixels(const std::string& text, double x, double y, bool centred,
                 const std::function<void(int, int, double)>& plot) {
  static LabelFont font;
  double width = 0;
  for (char ch : text)
    if (const ImFontGlyph* g = glyph(font, ch)) width += g->AdvanceX;
  if (centred) x -= width / 2;
  const double top = y - 10;  // the baseline sits ~10 px below the glyph box's top
  for (char ch : text) {
    const ImFontGlyph* g = glyph(font, ch);
    if (g == nullptr) continue;
    const int u0 = int(std::lround(g->U0 * font.width)), v0 = int(std::lround(g->V0 * font.height));
    const int gw = int(std::lround((g->U1 - g->U0) * font.width)),
              gh = int(std::lround((g->V1 - g->V0) * font.height));
    for (int j = 0; j < gh; ++j)
      for (int i = 0; i < gw; ++i)
        plot(int(std::lround(x + g->X0)) + i, int(std::lround(top + g->Y0)) + j,
             font.pixels[(v0 + j) * font.width + (u0 + i)] / 255.0);
    x += g->AdvanceX;
  }
}

const bool provided = [] {
  WindowServices services;
  services.render_painting = [](const paintcore::Painting& painting,
                                const render::RenderSettings& settings,
                                const std::filesystem::path& path) {
    render_gl::render_painting_gpu_to_file(painting, settings, path);
  };
  services.render_close_up =
      [](const paintcore::Painting& painting, const render::RenderSettings& settings,
         const render::CellRegion& region, int pixels_per_cell, const std::filesystem::path& path) {
        render_gl::render_painting_close_up_gpu_to_file(painting, settings, region, pixels_per_cell,
                                                        path);
      };
  services.spread_cost = gpu_spread_cost;
  services.text_pixels = text_pixels;
  provide_window_services(std::move(services));
  return true;
}();

}  // namespace
}  // namespace impasto::app
