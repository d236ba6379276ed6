// impasto bench marks: what the standard stroke leaves for each head and paint body
// (paintcore/marks_benchmark.hpp; docs/marks.md has the table).
#include <impasto/bench/marks.hpp>
#include <impasto/paintcore/brush_head.hpp>

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
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_marks_cmd {
namespace {

using namespace impasto::bench;  // the measures (bench/)

struct BenchMarksArgs {
  bool json = false;
  std::vector<std::string> heads;   // empty: every head in the brushes folder
  std::vector<std::string> bodies;  // empty: every body
  std::vector<std::string> params;  // NAME=VALUE
  bool sweeps = true;               // the sampling and resolution table after the first
  bench::MarkStroke stroke;
};

// The sample spacings (mm) and resolutions (dpi) of the second table: a mark must not
// depend on either (docs/marks.md, "No trace of the sampling").
constexpr double kSweepSpacingsMm[] = {0.05, 0.1, 0.5, 2.0};
constexpr double kSweepDpis[] = {150.0, 300.0, 600.0, 1200.0};

// One head and body's marks over the sweeps.
struct Sweep {
  std::string head, body;
  std::vector<bench::MarkFigures> by_spacing, by_dpi;
};

Sweep sweep(const std::string& head, paintcore::PaintBody body, const bench::MarkStroke& base) {
  Sweep s{head, std::string(paintcore::body_info(body).name), {}, {}};
  for (const double spacing : kSweepSpacingsMm) {
    bench::MarkStroke stroke = base;
    stroke.spacing_mm = spacing;
    s.by_spacing.push_back(bench::measure_mark(head, body, stroke));
  }
  for (const double dpi : kSweepDpis) {
    bench::MarkStroke stroke = base;
    stroke.dpi = dpi;
    s.by_dpi.push_back(bench::measure_mark(head, body, stroke));
  }
  return s;
}

void print_sweep_header() {
  std::printf("\n%-8s %-6s %31s %13s %7s %31s %15s\n", "", "", "trace % of film at spacing (mm)",
              "peak x median", "", "furrow rms (mm) at dpi", "furrow at mm");
  std::printf("%-8s %-6s %7s %7s %7s %7s %6s %6s %7s %7s %7s %7s %7s %7s %7s\n", "head", "body",
              "0.05", "0.1", "0.5", "2", "0.5", "2", "rim %", "150", "300", "600", "1200", "0.05",
              "2");
}

void print_sweep(const Sweep& s) {
  const auto& sp = s.by_spacing;
  const auto& dp = s.by_dpi;
  std::printf(
      "%-8s %-6s %7.2f %7.2f %7.2f %7.2f %6.1f %6.1f %7.1f %7.4f %7.4f %7.4f %7.4f %7.4f "
      "%7.4f\n",
      s.head.c_str(), s.body.c_str(), 100 * sp[0].trace_rms_share, 100 * sp[1].trace_rms_share,
      100 * sp[2].trace_rms_share, 100 * sp[3].trace_rms_share, sp[2].trace_peak, sp[3].trace_peak,
      100 * sp[1].lift_rim_share, dp[0].furrow_rms_mm, dp[1].furrow_rms_mm, dp[2].furrow_rms_mm,
      dp[3].furrow_rms_mm, sp[0].furrow_rms_mm, sp[3].furrow_rms_mm);
}

nlohmann::json sweep_json(const Sweep& s) {
  nlohmann::json spacings = nlohmann::json::array(), dpis = nlohmann::json::array();
  for (const auto& f : s.by_spacing)
    spacings.push_back({{"spacing_mm", f.spacing_mm},
                        {"trace_rms_share", f.trace_rms_share},
                        {"trace_peak", f.trace_peak},
                        {"trace_peak_share", f.trace_peak_share},
                        {"lift_rim_share", f.lift_rim_share},
                        {"furrow_rms_mm", f.furrow_rms_mm}});
  for (const auto& f : s.by_dpi)
    dpis.push_back(
        {{"dpi", f.dpi}, {"furrow_rms_mm", f.furrow_rms_mm}, {"middle_mm", f.middle_mm}});
  return {{"by_spacing", spacings}, {"by_dpi", dpis}};
}

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
    std::printf("%-8s %-6s %7s %6s %6s %6s %6s %7s %8s %8s %8s %7s %7s %6s %8s\n", "head", "body",
                "load", "dep%", "med", "p90", "p99", "ridge", "furrow", "rms", "bristle", "width",
                "trace%", "rim%", "us/step");
  ProgressReporter progress("bench marks", "marks");
  const std::uint64_t total = heads.size() * bodies.size() * (args.sweeps ? 2 : 1);
  std::uint64_t done = 0;
  std::vector<Sweep> sweeps;
  for (const std::string& head : heads)
    for (const paintcore::PaintBody body : bodies) {
      const bench::MarkFigures f = bench::measure_mark(head, body, args.stroke);
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
                                    {"trace_rms_share", f.trace_rms_share},
                                    {"trace_peak", f.trace_peak},
                                    {"trace_peak_share", f.trace_peak_share},
                                    {"lift_rim_share", f.lift_rim_share},
                                    {"steps", f.steps},
                                    {"seconds_per_step", f.seconds_per_step}}
                  << "\n";
      } else {
        std::printf(
            "%-8s %-6s %7.1f %6.1f %6.3f %6.3f %6.3f %7.3f %8.2f %8.3f %8.2f %7.2f %7.2f %6.1f "
            "%8.1f\n",
            head.c_str(), body_name.c_str(), f.load_mm3, 100.0 * f.deposited_share,
            f.thickness.median_mm, f.thickness.p90_mm, f.thickness.p99_mm, f.edge_ridge_mm,
            f.furrow_period_mm, f.furrow_rms_mm, f.bristle_spacing_mm, f.width_mm / f.size_mm,
            100.0 * f.trace_rms_share, 100.0 * f.lift_rim_share, 1e6 * f.seconds_per_step);
      }
      progress.update(++done, total);
      if (!args.sweeps) continue;
      Sweep s = sweep(head, body, args.stroke);
      progress.clear();
      if (args.json)
        std::cout << nlohmann::json{{"head", head}, {"body", body_name}, {"sweeps", sweep_json(s)}}
                  << "\n";
      sweeps.push_back(std::move(s));
      progress.update(++done, total);
    }
  if (args.json || sweeps.empty()) return;
  progress.clear();
  print_sweep_header();
  for (const Sweep& s : sweeps) print_sweep(s);
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
      ->check(finite_range(0.5, 50.0))
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
      ->check(finite_range(0.001, 10.0));
  add_threads_option(*cmd, args->stroke.threads);
  cmd->add_flag("!--no-sweeps", args->sweeps,
                "Skip the second table (sample spacings 0.05-2 mm, 150-1200 dpi)");
  cmd->add_option("--param", args->params, vocabulary_help("--param"));
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_marks_cmd
