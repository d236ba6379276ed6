#include "impasto/session/swatch.hpp"

#include <impasto/render/spectral_palette.hpp>

#include <impasto/render/display.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "impasto/session/replay.hpp"

namespace impasto::session {
namespace {

constexpr double kStrokeSpeedMmPerS = 50.0;
constexpr double kSampleSpacingMm = 0.2;
constexpr double kMaxSwatchBrushCells = 128.0;

int cells_for(double mm, double dpi) {
  return std::max(1, static_cast<int>(std::ceil(mm / paintcore::kMmPerInch * dpi)));
}

// The stroke's length and the room the brush needs around it.
double stroke_length_mm(const SwatchStroke& stroke) {
  return std::max(15.0, 3.0 * stroke.brush.size_mm);
}
double stroke_margin_mm(const SwatchStroke& stroke) {
  return stroke.brush.size_mm + 2.0;
}

}  // namespace

double swatch_dpi(const SwatchStroke& stroke) {
  return std::min(stroke.dpi, kMaxSwatchBrushCells / stroke.brush.size_mm * paintcore::kMmPerInch);
}

void paint_standard_stroke(paintcore::Painting& painting, const SwatchStroke& stroke,
                           double origin_x_mm, double origin_y_mm) {
  if (stroke.load.mix.empty()) throw std::runtime_error("swatch: the mix is empty");
  ReplayOptions options;
  options.threads = 1;
  SessionPlayer player(painting, options, false);
  player.apply(stroke.brush);
  player.apply(input::WipeEvent{});
  player.apply(stroke.load);
  const double length = stroke_length_mm(stroke);
  const auto samples = static_cast<int>(std::ceil(length / kSampleSpacingMm));
  for (int i = 0; i <= samples + 1; ++i) {
    const bool down = i <= samples;  // a last sample lifts the pen where it stopped
    const double along = length * std::min(i, samples) / samples;
    paintcore::PenSample sample;
    sample.time_s = along / kStrokeSpeedMmPerS + (down ? 0.0 : 0.01);
    sample.x_mm = origin_x_mm + along;
    sample.y_mm = origin_y_mm;
    sample.pressure = down ? stroke.pressure : 0.0f;
    sample.buttons = paintcore::kPenInRange | (down ? paintcore::kPenTip : 0u);
    player.apply(input::SampleEvent{sample});
  }
  player.finish();
}

paintcore::Painting paint_swatch_stroke(const SwatchStroke& stroke) {
  if (!(stroke.brush.size_mm > 0.0) || !std::isfinite(stroke.brush.size_mm))
    throw std::runtime_error("swatch: field 'size_mm' must be positive");
  const double length = stroke_length_mm(stroke);
  const double margin = stroke_margin_mm(stroke);
  const double dpi = swatch_dpi(stroke);
  paintcore::CanvasSpec spec{cells_for(length + 2.0 * margin, dpi), cells_for(2.0 * margin, dpi),
                             dpi, stroke.weave_seed};
  paintcore::validate(spec);
  paintcore::Painting painting(spec, 1);  // one thread: the window's simulation has the rest
  paint_standard_stroke(painting, stroke, margin, margin);
  return painting;
}

Deposit wet_deposit(const paintcore::Painting& painting) {
  const paintcore::Canvas& canvas = painting.canvas();
  std::vector<float> thickness;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const paintcore::Tile* tile = canvas.tile(index);
    if (!tile) continue;
    for (float v : tile->wet_volume_mm)
      if (v > kPaintedAboveMm) thickness.push_back(v);
  }
  Deposit deposit;
  deposit.painted_cells = thickness.size();
  if (thickness.empty()) return deposit;
  const auto middle = thickness.begin() + static_cast<std::ptrdiff_t>(thickness.size() / 2);
  std::nth_element(thickness.begin(), middle, thickness.end());
  deposit.median_mm = *middle;
  if (thickness.size() % 2 == 0) {  // the mean of the two middle values
    const float below = *std::max_element(thickness.begin(), middle);
    deposit.median_mm = 0.5 * (static_cast<double>(below) + *middle);
  }
  return deposit;
}

std::vector<std::uint8_t> stroke_area(const paintcore::Canvas& canvas) {
  const int w = canvas.width_cells(), h = canvas.height_cells();
  std::vector<std::uint8_t> area(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (int x = 0; x < w; ++x) {
    int first = h, last = -1;
    for (int y = 0; y < h; ++y)
      if (canvas.wet_volume_mm(x, y) > kPaintedAboveMm) {
        first = std::min(first, y);
        last = y;
      }
    for (int y = first; y <= last; ++y)
      area[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
           static_cast<std::size_t>(x)] = 1;
  }
  return area;
}

namespace {

// A renderer of these pigments with the rule settings ask for, or with `rule`.
render::TileRenderer renderer_of(const render::RenderSettings& settings,
                                 std::span<const std::string> slots,
                                 const render::SpectralSampling* rule) {
  if (!rule) return render::TileRenderer(settings, slots);
  return render::TileRenderer(settings, render::SpectralPalette(settings, slots, *rule));
}

}  // namespace

DisplayRgb mean_stroke_colour(const paintcore::Painting& painting,
                              const render::RenderSettings& settings,
                              const render::SpectralSampling* rule) {
  render::RenderSettings linear = settings;
  linear.display = render::DisplayEncoding::linear_srgb;
  linear.threads = 1;
  render::TileRenderer renderer = renderer_of(linear, painting.pigment_slots(), rule);
  const paintcore::Canvas& canvas = painting.canvas();
  renderer.render_all(canvas);
  const render::Image image = renderer.image();
  const std::vector<std::uint8_t> area = stroke_area(canvas);
  std::array<double, 3> sum{};
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!area[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                static_cast<std::size_t>(x)])
        continue;
      for (int c = 0; c < 3; ++c) sum[static_cast<std::size_t>(c)] += image.pixel(x, y)[c];
      ++count;
    }
  if (count == 0) {  // nothing painted: the ground
    const std::vector<input::PigmentPart> none = {};
    return render_flat_layers(settings, std::span(&none, 1), 0.0, rule).front();
  }
  // Linear sRGB back to XYZ, then through the display transform the renderer would use.
  static const std::array<double, 9> to_xyz = render::invert_3x3(render::xyz_to_linear_srgb());
  float xyz[3];
  for (int row = 0; row < 3; ++row) {
    double value = 0.0;
    for (int c = 0; c < 3; ++c)
      value += to_xyz[static_cast<std::size_t>(3 * row + c)] * sum[static_cast<std::size_t>(c)];
    xyz[row] = static_cast<float>(value / static_cast<double>(count));
  }
  render::DisplayTransform(settings.display).apply(xyz, 1);
  return {xyz[0], xyz[1], xyz[2]};
}

std::vector<DisplayRgb> render_flat_layers(const render::RenderSettings& settings,
                                           std::span<const std::vector<input::PigmentPart>> mixes,
                                           double thickness_mm,
                                           const render::SpectralSampling* rule) {
  if (!std::isfinite(thickness_mm) || thickness_mm < 0.0)
    throw std::runtime_error("swatch: the layer thickness must be finite and >= 0");
  render::RenderSettings flat = settings;
  flat.threads = 1;
  std::vector<DisplayRgb> colours;
  colours.reserve(mixes.size());
  // One row of cells, one mix each, all of the same thickness: every normal is straight up.
  // A painting holds at most kMaxPigmentSlots pigments, so the mixes go in batches.
  for (std::size_t first = 0; first < mixes.size();) {
    std::vector<std::string> slots;
    std::size_t end = first;
    for (; end < mixes.size() && end - first < static_cast<std::size_t>(paintcore::kTileSize);
         ++end) {
      std::vector<std::string> names = slots;
      for (const auto& part : mixes[end])
        if (std::find(names.begin(), names.end(), part.pigment) == names.end())
          names.push_back(part.pigment);
      if (names.size() > static_cast<std::size_t>(paintcore::kMaxPigmentSlots)) break;
      slots = std::move(names);
    }
    if (end == first)
      throw std::runtime_error("swatch: a mix has more than " +
                               std::to_string(paintcore::kMaxPigmentSlots) + " pigments");
    const int width = static_cast<int>(end - first);
    paintcore::Canvas canvas(paintcore::CanvasSpec{width, 1, 254.0, 0});
    paintcore::Tile& tile = canvas.ensure_tile(0, static_cast<int>(slots.size()));
    for (int x = 0; x < width; ++x) {
      const auto& mix = mixes[first + static_cast<std::size_t>(x)];
      if (mix.empty()) continue;  // the bare ground
      double total = 0.0;
      for (const auto& part : mix) total += part.parts;
      if (!(total > 0.0) || !std::isfinite(total))
        throw std::runtime_error("swatch: a mix's parts must add up to a positive number");
      tile.wet_volume_mm[static_cast<std::size_t>(x)] = static_cast<float>(thickness_mm);
      for (const auto& part : mix) {
        const auto slot = std::find(slots.begin(), slots.end(), part.pigment) - slots.begin();
        tile.pigment(static_cast<int>(slot))[x] +=
            static_cast<float>(thickness_mm * part.parts / total);
      }
    }
    render::TileRenderer renderer = renderer_of(flat, slots, rule);
    renderer.render_all(canvas);
    const render::Image image = renderer.image();
    for (int x = 0; x < width; ++x) {
      const float* rgb = image.pixel(x, 0);
      colours.push_back({rgb[0], rgb[1], rgb[2]});
    }
    first = end;
  }
  return colours;
}

double masstone_thickness_mm(const render::RenderSettings& settings) {
  return 1e4 * settings.thickness_scale_mm;
}

Swatch make_swatch(const SwatchStroke& stroke, const render::RenderSettings& settings,
                   const render::SpectralSampling* rule) {
  Swatch swatch;
  const paintcore::Painting painting = paint_swatch_stroke(stroke);
  swatch.deposit = wet_deposit(painting);
  swatch.on_canvas = mean_stroke_colour(painting, settings, rule);
  const std::vector<input::PigmentPart>& mix = stroke.load.mix;
  swatch.masstone =
      render_flat_layers(settings, std::span(&mix, 1), masstone_thickness_mm(settings), rule)
          .front();
  return swatch;
}

}  // namespace impasto::session
