// impasto bench marks: what the standard stroke leaves for each head and paint body
// (paintcore/marks_benchmark.hpp; docs/marks.md has the table).
#include <impasto/paintcore/brush_head.hpp>
#include <impasto/paintcore/marks_benchmark.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "progress.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_marks_cmd {
namespace {

struct BenchMarksArgs {
  bool json = false;
  std::vector<std::string> heads;   // empty: every head in the brushes folder
  std::vector<std::string> bodies;  // empty: every body
  std::vector<std::string> params;  // NAME=VALUE
  paintcore::MarkStroke stroke;
};

std::vector<std::string> all_heads() {
  std::vector<std::string> heads;
  for (const auto& entry : std::filesystem::directory_iterator(paintcore::default_brushes_dir()))
    if (entry.path().extension() == ".brush") heads.push_back(entry.path().stem().string());
  std::sort(heads.begin(), heads.end());
  return heads;
}

std::vector<std::string> paint_body_names_list() {
  std::vector<std::string> names;
  for (const auto& info : paintcore::kPaintBodies) names.emplace_back(info.name);
  return names;
}

void run(BenchMarksArgs args) {
  for (const std::string& assignment : args.params)
    paintcore::set_param(args.stroke.params, assignment);
  paintcore::validate(args.stroke.params);
  const std::vector<std::string> heads = args.heads.empty() ? all_heads() : args.heads;
  std::vector<paintcore::PaintBody> bodies;
  if (args.bodies.empty())
    for (const auto& info : paintcore::kPaintBodies) bodies.push_back(info.body);
  for (const std::string& name : args.bodies) {
    const auto body = paintcore::paint_body_from_name(name);
    if (!body)
      throw std::runtime_error("bench marks: --body '" + name.substr(0, 32) + "' is unknown (" +
                               paintcore::paint_body_names() + ")");
    bodies.push_back(*body);
  }
  if (!args.json)
    std::printf("%-8s %-6s %7s %6s %6s %6s %6s %7s %8s %8s %8s %7s %8s\n", "head", "body", "load",
                "dep%", "med", "p90", "p99", "ridge", "furrow", "rms", "bristle", "width",
                "us/step");
  ProgressReporter progress("bench marks", "marks");
  const std::uint64_t total = heads.size() * bodies.size();
  std::uint64_t done = 0;
  for (const std::string& head : heads)
    for (const paintcore::PaintBody body : bodies) {
      const paintcore::MarkFigures f = paintcore::measure_mark(head, body, args.stroke);
      progress.clear();  // the row goes where the bar was; the bar again below it
      const std::string body_name(paintcore::body_info(body).name);
      if (args.json) {
        std::cout << nlohmann::json{{"head", head},
                                    {"body", body_name},
                                    {"size_mm", f.size_mm},
                                    {"load_mm3", f.load_mm3},
                                    {"deposited_share", f.deposited_share},
                                    {"thickness_mm",
                                     {{"median", f.thickness.median_mm},
                                      {"p90", f.thickness.p90_mm},
                                      {"p99", f.thickness.p99_mm},
                                      {"max", f.thickness.max_mm}}},
                                    {"edge_ridge_mm", f.edge_ridge_mm},
                                    {"furrow_period_mm", f.furrow_period_mm},
                                    {"furrow_rms_mm", f.furrow_rms_mm},
                                    {"bristle_spacing_mm", f.bristle_spacing_mm},
                                    {"width_mm", f.width_mm},
                                    {"head_width_mm", f.size_mm},
                                    {"steps", f.steps},
                                    {"seconds_per_step", f.seconds_per_step}}
                  << "\n";
      } else {
        std::printf("%-8s %-6s %7.1f %6.1f %6.3f %6.3f %6.3f %7.3f %8.2f %8.3f %8.2f %7.2f %8.1f\n",
                    head.c_str(), body_name.c_str(), f.load_mm3, 100.0 * f.deposited_share,
                    f.thickness.median_mm, f.thickness.p90_mm, f.thickness.p99_mm, f.edge_ridge_mm,
                    f.furrow_period_mm, f.furrow_rms_mm, f.bristle_spacing_mm,
                    f.width_mm / f.size_mm, 1e6 * f.seconds_per_step);
      }
      progress.update(++done, total);
    }
}

const CommandRegistrar registrar("bench marks", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  auto args = std::make_shared<BenchMarksArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "marks", "What the standard stroke leaves for each head and paint body (docs/marks.md)");
  add_json_flag(*cmd, args->json, "one object a line, per head and body");
  cmd->add_option("--head", args->heads, "Heads to measure (default: every head)");
  cmd->add_option("--body", args->bodies, "Paint bodies (default: all)")
      ->check(CLI::IsMember(paint_body_names_list()));
  add_dpi_option(*cmd, args->stroke.dpi, {}, 20.0, 1200.0);
  cmd->add_option("--head-mm", args->stroke.size_mm, "Head width (mm)")
      ->check(CLI::Range(0.5, 50.0))
      ->capture_default_str();
  add_deprecated_option(*cmd, "--size", "--head-mm", [args](const std::string& text) {
    // --size is a canvas's WxH everywhere else; here it was the head's width in mm.
    std::size_t used = 0;
    double mm = 0.0;
    try {
      mm = std::stod(text, &used);
    } catch (const std::exception&) {
    }
    if (used != text.size() || !(mm >= 0.5 && mm <= 50.0))
      throw std::runtime_error("--size " + text + ": expected the head's width in mm, 0.5..50");
    args->stroke.size_mm = mm;
  });
  cmd->add_option("--spacing", args->stroke.spacing_mm, "Distance between pen samples (mm)")
      ->check(CLI::Range(0.001, 10.0));
  add_threads_option(*cmd, args->stroke.threads);
  cmd->add_option("--param", args->params, vocabulary_help("--param"));
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_marks_cmd
