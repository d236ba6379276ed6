// impasto bench frontier: colour error against cost for every node count, rule and storage
// (the speed/accuracy frontier of N-wavelength rendering): per light, mean and max CIEDE2000
// of the bench samples against the 1-nm spectrum (bench color's samples, held out from the
// trained rules' paints), ns per cell of the per-frame kernel, and the time to build the rule
// for the light. A row is on the frontier when no other row under the same light is as cheap
// (costs within either's run-to-run spread count as equal) and more accurate. --svg plots
// mean error against ns per cell.
#include <impasto/data/cie.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/files/atomic_file.hpp>
#include <impasto/render/color_accuracy.hpp>
#include <impasto/render/node_cache.hpp>
#include <impasto/render/node_optimisation.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_frontier_cmd {
namespace {

using namespace impasto::render;

struct BenchFrontierArgs {
  bool json = false;
  std::vector<int> nodes{3, 4, 6, 8, 12, 16};
  std::vector<std::string> lights{"D65", "A", "F11"};
  std::vector<std::string> rules = util::names_of(kNodeWeightsNames);
  int timing_cells = 20000;
  std::string svg;  // plot file, empty: none
};

struct FrontierRow {
  AccuracyResult result;
  std::string rule;
  double build_ms = 0.0;   // the rule for this light, N and palette, built from scratch
  double cached_ms = 0.0;  // the same rule read back from the disk cache
  bool frontier = false;
};

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void mark_frontier(std::vector<FrontierRow>& rows) {
  std::vector<CostAndError> points;
  for (const FrontierRow& row : rows)
    points.push_back({row.result.light, row.result.ns_per_cell, row.result.ns_per_cell_spread,
                      row.result.mean_de00});
  const std::vector<bool> on = frontier_points(points);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].frontier = on[i];
}

// Mean ΔE00 (log) against ns per cell (log), one colour per rule, filled for float storage,
// hollow for half; one panel per light side by side.
std::string frontier_svg(const std::vector<FrontierRow>& rows,
                         const std::vector<std::string>& lights,
                         const std::vector<std::string>& rules) {
  constexpr double kPanelW = 320, kPanelH = 260, kLeft = 50, kTop = 30, kBottom = 40;
  const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  double t0 = 1e300, t1 = 0, e0 = 1e300, e1 = 1e-3;
  for (const FrontierRow& r : rows) {
    t0 = std::min(t0, r.result.ns_per_cell);
    t1 = std::max(t1, r.result.ns_per_cell);
    if (r.result.nodes == 0) continue;  // exact: drawn on the bottom edge
    e0 = std::min(e0, r.result.mean_de00);
    e1 = std::max(e1, r.result.mean_de00);
  }
  const double lt0 = std::log10(t0 * 0.8), lt1 = std::log10(t1 * 1.25);
  const double le0 = std::log10(e0 * 0.8), le1 = std::log10(e1 * 1.25);
  std::ostringstream svg;
  const double width = kLeft + kPanelW * static_cast<double>(lights.size()) + 20;
  const double height = kTop + kPanelH + kBottom + 20.0 * static_cast<double>(rules.size());
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t p = 0; p < lights.size(); ++p) {
    const double x0 = kLeft + kPanelW * static_cast<double>(p), y0 = kTop;
    const double w = kPanelW - 30, h = kPanelH;
    const auto px = [&](double ns) { return x0 + w * (std::log10(ns) - lt0) / (lt1 - lt0); };
    const auto py = [&](double de) {
      return de <= 0.0 ? y0 + h : y0 + h - h * (std::log10(de) - le0) / (le1 - le0);
    };
    svg << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << w << "\" height=\"" << h
        << "\" fill=\"none\" stroke=\"#888\"/>\n"
        << "<text x=\"" << x0 + 4 << "\" y=\"" << y0 - 8 << "\">" << lights[p]
        << ": mean ΔE00 (log) vs ns per cell (log)</text>\n";
    for (double de : {0.1, 0.3, 1.0, 3.0}) {
      if (std::log10(de) < le0 || std::log10(de) > le1) continue;
      svg << "<line x1=\"" << x0 << "\" x2=\"" << x0 + w << "\" y1=\"" << py(de) << "\" y2=\""
          << py(de) << "\" stroke=\"#ddd\"/><text x=\"" << x0 - 28 << "\" y=\"" << py(de) + 4
          << "\">" << de << "</text>\n";
    }
    for (double ns : {30.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0}) {
      if (std::log10(ns) < lt0 || std::log10(ns) > lt1) continue;
      svg << "<line y1=\"" << y0 << "\" y2=\"" << y0 + h << "\" x1=\"" << px(ns) << "\" x2=\""
          << px(ns) << "\" stroke=\"#ddd\"/><text y=\"" << y0 + h + 14 << "\" x=\"" << px(ns) - 10
          << "\">" << ns << "</text>\n";
    }
    for (const FrontierRow& r : rows) {
      if (r.result.light != lights[p]) continue;
      const auto rule =
          static_cast<std::size_t>(std::find(rules.begin(), rules.end(), r.rule) - rules.begin());
      const bool half = r.result.storage == ReflectanceStorage::float16;
      svg << "<circle cx=\"" << px(r.result.ns_per_cell) << "\" cy=\"" << py(r.result.mean_de00)
          << "\" r=\"" << (half ? 5 : 3.5) << "\" fill=\"" << (half ? "none" : colours[rule % 6])
          << "\" stroke=\"" << colours[rule % 6] << "\"/>\n";
      if (!half) {
        svg << "<text x=\"" << px(r.result.ns_per_cell) + 5 << "\" y=\""
            << py(r.result.mean_de00) - 4 << "\" font-size=\"8\" fill=\"" << colours[rule % 6]
            << "\">" << (r.result.nodes == 0 ? std::string("full") : std::to_string(r.result.nodes))
            << "</text>\n";
      }
    }
  }
  for (std::size_t k = 0; k < rules.size(); ++k) {
    const double y = kTop + kPanelH + kBottom + 20.0 * static_cast<double>(k);
    svg << "<circle cx=\"" << kLeft + 6 << "\" cy=\"" << y - 4 << "\" r=\"3.5\" fill=\""
        << colours[k % 6] << "\"/><text x=\"" << kLeft + 16 << "\" y=\"" << y << "\">" << rules[k]
        << " (filled: float storage, ring: half; numbers: N)</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

void run(const BenchFrontierArgs& args) {
  const std::vector<data::Pigment>& pigments = data::PigmentDatabase::defaults().all();
  const std::vector<ColorSample> samples = standard_color_samples(pigments);
  const data::Spectrum ground = hiding_reflectance(data::PigmentDatabase::defaults().get("White"));
  std::vector<FrontierRow> rows;
  for (const std::string& light_name : args.lights) {
    const data::Spectrum light = data::light_from_spec(light_name);
    for (const std::string& rule_name : args.rules) {
      const NodeWeights rule = parse_node_weights(rule_name);
      for (int n : args.nodes) {
        // The rule for this light built from scratch (what a new palette or light costs
        // once), kept on disk, and read back as a later run finds it; the rows below reuse it.
        const auto& cmf = data::cie1931_2deg();
        double build_ms = 0.0, cached_ms = 0.0;
        const bool trained = rule == NodeWeights::fitted || rule == NodeWeights::optimised;
        if (trained) {
          const auto start = std::chrono::steady_clock::now();
          const SpectralSampling built =
              build_palette_rule(light, cmf, n, {}, rule, pigments, ground);
          build_ms = ms_since(start);
          store_node_rule(palette_rule_key(light, cmf, n, {}, rule, pigments, ground), built);
          forget_palette_rules_in_memory();
        }
        const auto start = std::chrono::steady_clock::now();
        make_palette_sampling(light, cmf, n, {}, rule, pigments, ground);
        (trained ? cached_ms : build_ms) = ms_since(start);  // the Gaussian rules: no cache
        for (ReflectanceStorage storage :
             {ReflectanceStorage::float32, ReflectanceStorage::float16}) {
          rows.push_back({evaluate_color_accuracy(light, light_name, n, pigments, samples, storage,
                                                  rule, args.timing_cells),
                          rule_name, build_ms, cached_ms, false});
        }
      }
    }
    // The full spectrum: the reference itself, its cost.
    rows.push_back({evaluate_color_accuracy(light, light_name, 0, pigments, samples,
                                            ReflectanceStorage::float32, NodeWeights::interpolatory,
                                            args.timing_cells),
                    "full", 0.0, 0.0, false});
  }
  mark_frontier(rows);
  if (!args.svg.empty()) {
    std::vector<std::string> rules = args.rules;
    rules.push_back("full");
    files::write_file_atomically(args.svg, frontier_svg(rows, args.lights, rules));
  }
  if (args.json) {
    for (const FrontierRow& r : rows) {
      std::cout << nlohmann::json{{"light", r.result.light},
                                  {"n", r.result.nodes},
                                  {"rule", r.rule},
                                  {"storage", r.result.storage == ReflectanceStorage::float16
                                                  ? "half"
                                                  : "float"},
                                  {"mean_de00", r.result.mean_de00},
                                  {"max_de00", r.result.max_de00},
                                  {"ns_per_cell", r.result.ns_per_cell},
                                  {"ns_per_cell_spread", r.result.ns_per_cell_spread},
                                  {"build_ms", r.build_ms},
                                  {"cached_ms", r.cached_ms},
                                  {"frontier", r.frontier}}
                       .dump()
                << "\n";
    }
    return;
  }
  std::printf(
      "%zu samples (%zu pigments); * = on the frontier (no row under the light as cheap, "
      "within the timing runs' spread, and more accurate)\n",
      samples.size(), pigments.size());
  std::printf("%-6s %4s %-14s %-6s %10s %10s %10s %10s %10s\n", "light", "N", "rule", "store",
              "mean dE00", "max dE00", "ns/cell", "build ms", "cached ms");
  for (const FrontierRow& r : rows) {
    std::printf(
        "%-6s %4s %-14s %-6s %10.4f %10.4f %10.1f %10.1f %10.2f %s\n", r.result.light.c_str(),
        r.result.nodes == 0 ? "full" : std::to_string(r.result.nodes).c_str(), r.rule.c_str(),
        r.result.storage == ReflectanceStorage::float16 ? "half" : "float", r.result.mean_de00,
        r.result.max_de00, r.result.ns_per_cell, r.build_ms, r.cached_ms, r.frontier ? "*" : "");
  }
}

const CommandRegistrar registrar("bench frontier", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "frontier", "Colour error against cost for every node count, rule and storage");
  auto args = std::make_shared<BenchFrontierArgs>();
  cmd->add_flag("--json", args->json,
                "One JSON object per row: light, n, rule, storage, mean_de00, max_de00, "
                "ns_per_cell, build_ms, cached_ms, frontier");
  cmd->add_option("--nodes", args->nodes, "Wavelength counts (1..16)")->check(finite_range(1, 16));
  cmd->add_option("--lights", args->lights, "Lights (D65, A, F11, blackbody:K, FILE.csv)");
  cmd->add_option("--rules", args->rules, "Node rules")
      ->check(CLI::IsMember(util::names_of(kNodeWeightsNames)));
  cmd->add_option("--cells", args->timing_cells, "Cells per timing run")
      ->check(finite_range(1, 10000000));
  cmd->add_option("--svg", args->svg, "Also plot mean error against ns per cell to FILE.svg");
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_frontier_cmd
