// impasto cracks: make crack maps (craquelure, PNG import) and evaluate single cavities.
#include <impasto/cracks/craquelure.hpp>
#include <impasto/cracks/gouffe.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "command.hpp"

namespace impasto::app {
namespace {

using namespace impasto::cracks;

struct GenerateArgs {
  int width = 1024, height = 1024;
  double cell_mm = 0.1;
  double thickness_mm = 0.2;
  std::string shape = "v-groove";
  std::string out;
  double max_depth_mm = 0.5;
  CraquelureSettings settings;
};

// Statistics of a crack map, printed as one JSON line.
void print_stats(const CrackMap& map) {
  double max_depth = 0.0, max_half_width = 0.0;
  map.for_each_crack([&](int, int, const CrackCell& c) {
    max_depth = std::max(max_depth, static_cast<double>(c.depth_mm));
    max_half_width = std::max(max_half_width, static_cast<double>(c.half_width_mm));
  });
  const nlohmann::json stats = {{"crack_cells", map.crack_cells()},
                                {"tiles_with_cracks", map.allocated_tiles()},
                                {"tiles", map.tiles_x() * map.tiles_y()},
                                {"networks", count_crack_networks(map)},
                                {"max_depth_mm", max_depth},
                                {"max_half_width_mm", max_half_width},
                                {"memory_bytes", map.memory_bytes()}};
  std::cout << stats.dump() << "\n";
}

void run_generate(const GenerateArgs& args) {
  CrackMap map(args.width, args.height, args.cell_mm);
  CraquelureSettings settings = args.settings;
  settings.shape = shape_from_name(args.shape);
  PaintFilm film;
  film.uniform_thickness_mm = args.thickness_mm;
  generate_craquelure(map, film, settings);
  if (!args.out.empty()) write_crack_png(map, args.out, args.max_depth_mm);
  print_stats(map);
}

struct ImportArgs {
  std::string png;
  std::string shape = "v-groove";
  CrackImageSettings settings;
};

void run_import(const ImportArgs& args) {
  CrackImageSettings settings = args.settings;
  settings.shape = shape_from_name(args.shape);
  print_stats(read_crack_png(args.png, settings));
}

struct CavityArgs {
  std::string shape = "v-groove";
  double depth_mm = 0.2, half_width_mm = 0.05, rho0 = 0.5;
};

void run_cavity(const CavityArgs& args) {
  const CavityShape shape = shape_from_name(args.shape);
  if (!(args.rho0 >= 0.0 && args.rho0 <= 1.0)) throw std::runtime_error("--rho0 must be in [0, 1]");
  const ViewFactors vf = view_factors(shape, {args.depth_mm, args.half_width_mm});
  const nlohmann::json out = {{"shape", args.shape},
                              {"F", vf.F},
                              {"G", vf.G},
                              {"apparent_reflectance", apparent_reflectance(args.rho0, vf)},
                              {"apparent_emissivity", apparent_emissivity(args.rho0, vf)},
                              {"first_order", apparent_reflectance_first_order(args.rho0, vf)},
                              {"second_order", apparent_reflectance_second_order(args.rho0, vf)}};
  std::cout << out.dump() << "\n";
}

const CommandRegistrar registrar("cracks", [](CLI::App& root) {
  CLI::App* group = command_group(root, "cracks", "Cracks and holes as grey-body cavities");

  auto gen = std::make_shared<GenerateArgs>();
  CLI::App* g = group->add_subcommand("generate", "Generate a craquelure crack map");
  g->add_option("--width", gen->width, "Canvas width in cells")->check(CLI::Range(1, 1 << 17));
  g->add_option("--height", gen->height, "Canvas height in cells")->check(CLI::Range(1, 1 << 17));
  g->add_option("--cell-mm", gen->cell_mm, "Cell size (mm)")->check(CLI::PositiveNumber);
  g->add_option("--thickness-mm", gen->thickness_mm, "Dry paint film thickness (mm)")
      ->check(CLI::NonNegativeNumber);
  g->add_option("--seed", gen->settings.seed, "Random seed");
  g->add_option("--island-mm", gen->settings.island_size_mm, "Mean island size (mm)")
      ->check(CLI::PositiveNumber);
  g->add_option("--age-years", gen->settings.age_years, "Age of the painting (years)")
      ->check(CLI::NonNegativeNumber);
  g->add_option("--jitter", gen->settings.jitter, "Island jitter, 0..1")
      ->check(CLI::Range(0.0, 1.0));
  g->add_option("--shape", gen->shape, "Crack section: arc-groove, v-groove or box-groove");
  g->add_option("--out", gen->out, "Write the depths as a 16-bit grey PNG");
  g->add_option("--max-depth-mm", gen->max_depth_mm, "Depth drawn white in --out (mm)")
      ->check(CLI::PositiveNumber);
  g->callback([gen] { run_generate(*gen); });

  auto imp = std::make_shared<ImportArgs>();
  CLI::App* i = group->add_subcommand("import", "Read a crack map from a grey PNG (grey = depth)");
  i->add_option("png", imp->png, "PNG file")->required();
  i->add_option("--cell-mm", imp->settings.cell_mm, "Cell size (mm)")->check(CLI::PositiveNumber);
  i->add_option("--max-depth-mm", imp->settings.max_depth_mm, "Depth of white (mm)")
      ->check(CLI::PositiveNumber);
  i->add_option("--depth-to-half-width", imp->settings.depth_to_half_width, "L / R")
      ->check(CLI::PositiveNumber);
  i->add_option("--shape", imp->shape, "Crack section: arc-groove, v-groove, box-groove, ...");
  i->callback([imp] { run_import(*imp); });

  auto cav = std::make_shared<CavityArgs>();
  CLI::App* c = group->add_subcommand("cavity", "F, G and apparent reflectance of one cavity");
  c->add_option("--shape", cav->shape,
                "arc-groove, v-groove, box-groove, sphere-pit, cone-pit, cylinder-pit");
  c->add_option("--depth-mm", cav->depth_mm, "Depth L (mm)")->check(CLI::NonNegativeNumber);
  c->add_option("--half-width-mm", cav->half_width_mm, "Half-width R (mm)")
      ->check(CLI::PositiveNumber);
  c->add_option("--rho0", cav->rho0, "Wall reflectance, 0..1");
  c->callback([cav] { run_cavity(*cav); });
});

}  // namespace
}  // namespace impasto::app
