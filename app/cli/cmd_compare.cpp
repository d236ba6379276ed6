// impasto compare A B: how far two paintings (or a painting and an image, or two images) are
// apart as a viewer sees them — CIEDE2000 per pixel under D65 (mean, 95th percentile, max,
// pixels over a threshold) and, for two paintings, the surface height in mm — with a
// difference image and an exit status, so that a playback test is one line.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/image.hpp>

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
#include "comparison.hpp"
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
  render::Image linear;  // linear sRGB (PNGs only)
};

Side load_side(const std::string& file) {
  Side side;
  if (is_painting(file)) {
    side.painting = paintcore::Painting::load(file);
    return side;
  }
  side.linear = render::read_png(file);
  for (float& v : side.linear.rgb) v = static_cast<float>(render::srgb_decoded(v));
  return side;
}

void run(const CompareArgs& args) {
  const Side first = load_side(args.first), second = load_side(args.second);
  const Comparison c =
      first.painting && second.painting
          ? compare_paintings(*first.painting, *second.painting, args.threshold, args.first,
                              args.second)
          : compare_images(first.painting ? linear_view(*first.painting) : first.linear,
                           second.painting ? linear_view(*second.painting) : second.linear,
                           args.threshold, args.first, args.second);
  nlohmann::json report{
      {"first", args.first},    {"second", args.second},       {"width", c.width},
      {"height", c.height},     {"de00_mean", c.de00_mean},    {"de00_p95", c.de00_p95},
      {"de00_max", c.de00_max}, {"threshold", args.threshold}, {"pixels_over", c.pixels_over}};
  if (c.height_mm_max) {
    report["height_mm_mean"] = *c.height_mm_mean;
    report["height_mm_max"] = *c.height_mm_max;
  }
  if (!args.out.empty()) {
    // The difference: 0 black, the threshold mid-grey, 10 or more white.
    render::Image diff{c.width, c.height, std::vector<float>(c.de00.size() * 3)};
    for (std::size_t i = 0; i < c.de00.size(); ++i) {
      const auto v = static_cast<float>(std::min(1.0, c.de00[i] / 10.0));
      diff.rgb[3 * i] = diff.rgb[3 * i + 1] = diff.rgb[3 * i + 2] = std::sqrt(v);
    }
    render::write_png(args.out, diff);
  }
  if (args.json) {
    std::cout << report.dump(2) << "\n";
  } else {
    std::printf("dE00 mean %.3f, p95 %.3f, max %.3f; %ld of %zu pixels over %.2f\n", c.de00_mean,
                c.de00_p95, c.de00_max, c.pixels_over, c.de00.size(), args.threshold);
    if (c.height_mm_max)
      std::printf("height difference mean %.4f mm, max %.4f mm\n", *c.height_mm_mean,
                  *c.height_mm_max);
  }
  if (args.max_de00 >= 0.0 && c.de00_max > args.max_de00) {
    char text[96];
    std::snprintf(text, sizeof text, "compare: dE00 max %.3f is above --max-de00 %.3f", c.de00_max,
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
