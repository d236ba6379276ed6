// impasto compare A B: how far two paintings (or a painting and an image, or two images) are
// apart as a viewer sees them — CIEDE2000 per pixel under D65 (mean, 95th percentile, max,
// pixels over a threshold) and, for two paintings, the surface height in mm — with a
// difference image and an exit status, so that a playback test is one line.
#include <impasto/data/colorimetry.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/image.hpp>
#include <impasto/render/relief_maps.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::compare_cmd {
namespace {

struct CompareArgs {
  std::string first, second;
  std::string out;         // the difference image, optional
  double threshold = 1.0;  // ΔE00 a pixel counts as different from
  double max_de00 = -1.0;  // < 0: no exit status from the colour
  bool json = false;
};

bool is_painting(const std::string& file) {
  return std::filesystem::path(file).extension() == ".impasto";
}

// One side of the comparison: a painting (kept, for its heights) or a PNG.
struct Side {
  std::optional<paintcore::Painting> painting;
  render::Image linear;  // linear sRGB
};

// A painting rendered with the default settings, or a PNG decoded; linear sRGB either way.
Side load_side(const std::string& file) {
  Side side;
  if (is_painting(file)) {
    side.painting = paintcore::Painting::load(file);
    render::RenderSettings settings;
    settings.display = render::DisplayEncoding::linear_srgb;
    side.linear = render::render_painting(*side.painting, settings);
    return side;
  }
  side.linear = render::read_png(file);
  for (float& v : side.linear.rgb) v = static_cast<float>(render::srgb_decoded(v));
  return side;
}

std::vector<data::Lab> to_lab(const render::Image& image) {
  const auto m = render::invert_3x3(render::xyz_to_linear_srgb());
  const data::Xyz white = data::white_point(data::light_from_spec("D65"));
  std::vector<data::Lab> lab;
  lab.reserve(image.rgb.size() / 3);
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    const double r = image.rgb[i], g = image.rgb[i + 1], b = image.rgb[i + 2];
    const data::Xyz xyz{100.0 * (m[0] * r + m[1] * g + m[2] * b),
                        100.0 * (m[3] * r + m[4] * g + m[5] * b),
                        100.0 * (m[6] * r + m[7] * g + m[8] * b)};
    lab.push_back(data::xyz_to_lab(xyz, white));
  }
  return lab;
}

void run(const CompareArgs& args) {
  const Side first = load_side(args.first), second = load_side(args.second);
  const render::Image &a = first.linear, &b = second.linear;
  if (a.width != b.width || a.height != b.height) {
    throw std::runtime_error("compare: " + args.first + " is " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + ", " + args.second + " is " +
                             std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  const std::vector<data::Lab> la = to_lab(a), lb = to_lab(b);
  std::vector<double> de(la.size());
  for (std::size_t i = 0; i < la.size(); ++i) de[i] = data::ciede2000(la[i], lb[i]);
  double mean = 0.0;
  long over = 0;
  for (double d : de) {
    mean += d / static_cast<double>(de.size());
    over += d > args.threshold;
  }
  std::vector<double> sorted = de;
  std::sort(sorted.begin(), sorted.end());
  const double p95 =
      sorted[static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size() - 1))];
  const double max = sorted.back();
  nlohmann::json report{
      {"first", args.first}, {"second", args.second},       {"width", a.width},
      {"height", a.height},  {"de00_mean", mean},           {"de00_p95", p95},
      {"de00_max", max},     {"threshold", args.threshold}, {"pixels_over", over}};
  if (first.painting && second.painting) {
    const render::HeightGrid ha = render::surface_heights(first.painting->canvas());
    const render::HeightGrid hb = render::surface_heights(second.painting->canvas());
    double height_max = 0.0, height_mean = 0.0;
    for (std::size_t i = 0; i < ha.mm.size() && i < hb.mm.size(); ++i) {
      const double d = std::abs(static_cast<double>(ha.mm[i]) - hb.mm[i]);
      height_max = std::max(height_max, d);
      height_mean += d / static_cast<double>(ha.mm.size());
    }
    report["height_mm_mean"] = height_mean;
    report["height_mm_max"] = height_max;
  }
  if (!args.out.empty()) {
    // The difference: 0 black, the threshold mid-grey, 10 or more white.
    render::Image diff{a.width, a.height, std::vector<float>(a.rgb.size())};
    for (std::size_t i = 0; i < de.size(); ++i) {
      const auto v = static_cast<float>(std::min(1.0, de[i] / 10.0));
      diff.rgb[3 * i] = diff.rgb[3 * i + 1] = diff.rgb[3 * i + 2] = std::sqrt(v);
    }
    render::write_png(args.out, diff);
  }
  if (args.json) {
    std::cout << report.dump(2) << "\n";
  } else {
    std::printf("dE00 mean %.3f, p95 %.3f, max %.3f; %ld of %zu pixels over %.2f\n", mean, p95, max,
                over, de.size(), args.threshold);
    if (report.contains("height_mm_max")) {
      std::printf("height difference mean %.4f mm, max %.4f mm\n",
                  report["height_mm_mean"].get<double>(), report["height_mm_max"].get<double>());
    }
  }
  if (args.max_de00 >= 0.0 && max > args.max_de00) {
    char text[96];
    std::snprintf(text, sizeof text, "compare: dE00 max %.3f is above --max-de00 %.3f", max,
                  args.max_de00);
    throw std::runtime_error(text);
  }
}

void setup(CLI::App& root) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = root.add_subcommand(
      "compare", "How far two paintings or images are apart (dE00 per pixel, heights)");
  cmd->add_option("first", args->first, "A painting (.impasto) or a PNG")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("second", args->second, "Another, of the same size")
      ->required()
      ->check(CLI::ExistingFile);
  add_out_option(*cmd, args->out, "a PNG of the difference (black: none, white: dE00 10 or more)");
  cmd->add_option("--threshold", args->threshold, "dE00 a pixel counts as different from")
      ->check(finite_range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--max-de00", args->max_de00,
                  "Fail (exit status 1) when the largest dE00 is above this")
      ->check(finite_range(0.0, 100.0));
  add_json_flag(*cmd, args->json, "the figures in one object");
  cmd->callback([args] { run(*args); });
}

const CommandRegistrar registrar("compare", setup);

}  // namespace
}  // namespace impasto::app::compare_cmd
