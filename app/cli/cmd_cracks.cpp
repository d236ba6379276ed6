// impasto cracks: make crack maps (craquelure, PNG import, the crack brush), alone or in a
// painting file, and evaluate single cavities.
#include <impasto/cracks/cavity_correction.hpp>
#include <impasto/cracks/cavity_table.hpp>
#include <impasto/cracks/crack_layer_maps.hpp>
#include <impasto/cracks/craquelure.hpp>
#include <impasto/cracks/gouffe.hpp>
#include <impasto/files/atomic_file.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "command.hpp"
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::cracks_cmd {
namespace {

using namespace impasto::cracks;

struct GenerateArgs {
  std::optional<CanvasSize> size;  // of the uniform film; default 1024x1024
  double cell_mm = 0.1;
  double thickness_mm = 0.2;
  std::string shape{shape_name(CavityShape::VGroove)};
  std::string out;
  double max_depth_mm = 0.5;
  CraquelureSettings settings;
  std::string painting;  // crack this painting's dry layers instead of a uniform film
  bool dry = false;      // dry the painting's wet paint first
  std::string save;      // where the cracked painting goes
};

// A painting file named by --painting, and where --save puts it after the cracks change.
paintcore::Painting load_for_cracks(const std::string& painting, const std::string& save) {
  if (save.empty()) throw std::runtime_error("--painting needs --save FILE.impasto");
  return paintcore::Painting::load(painting);
}

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
  CraquelureSettings settings = args.settings;
  settings.shape = shape_from_name(args.shape);
  if (!is_groove(settings.shape)) throw std::runtime_error("--shape: craquelure makes grooves");
  if (!args.painting.empty()) {
    paintcore::Painting painting = load_for_cracks(args.painting, args.save);
    if (args.dry) painting.dry(1.0);
    crack_painting(painting, settings);
    const CrackMap map = crack_map_of(painting);
    if (!args.out.empty()) write_crack_png(map, args.out, args.max_depth_mm);
    painting.save(args.save);
    print_stats(map);
    return;
  }
  const CanvasSize size = args.size.value_or(CanvasSize{1024, 1024});
  CrackMap map(size.width, size.height, args.cell_mm);
  PaintFilm film;
  film.uniform_thickness_mm = args.thickness_mm;
  generate_craquelure(map, film, settings);
  if (!args.out.empty()) write_crack_png(map, args.out, args.max_depth_mm);
  print_stats(map);
}

struct ImportArgs {
  std::string png;
  std::string shape{shape_name(CavityShape::VGroove)};
  CrackImageSettings settings;
  std::string painting, save;  // put the map into this painting, saved there
};

void run_import(const ImportArgs& args) {
  CrackImageSettings settings = args.settings;
  settings.shape = shape_from_name(args.shape);
  if (args.painting.empty()) {
    print_stats(read_crack_png(args.png, settings));
    return;
  }
  paintcore::Painting painting = load_for_cracks(args.painting, args.save);
  settings.cell_mm = painting.canvas().cell_mm();
  const CrackMap map = read_crack_png(args.png, settings);
  set_painting_cracks(painting, map);
  painting.save(args.save);
  print_stats(map);
}

struct BrushArgs {
  std::string painting, save;
  std::string points;  // "x,y x,y ..." in mm
  std::string shape{shape_name(CavityShape::VGroove)};
  double depth_mm = 0.1, half_width_mm = 0.05;
  int exposed_layer = -1;  // -1: the canvas ground
};

// "x,y x,y ..." (mm) as points; throws naming the bad item.
std::vector<std::array<double, 2>> parse_points(const std::string& text) {
  std::vector<std::array<double, 2>> points;
  std::istringstream in(text);
  std::string item;
  while (in >> item) {
    std::array<double, 2> p{};
    char comma = 0;
    std::istringstream pair(item);
    if (!(pair >> p[0] >> comma >> p[1]) || comma != ',' || !pair.eof() || !std::isfinite(p[0]) ||
        !std::isfinite(p[1])) {
      throw std::runtime_error("--points: '" + item + "' is not x,y in mm");
    }
    points.push_back(p);
  }
  if (points.empty()) throw std::runtime_error("--points: no points");
  return points;
}

void run_brush(const BrushArgs& args) {
  paintcore::Painting painting = load_for_cracks(args.painting, args.save);
  CrackStroke stroke;
  stroke.points_mm = parse_points(args.points);
  stroke.shape = shape_from_name(args.shape);
  stroke.depth_mm = args.depth_mm;
  stroke.half_width_mm = args.half_width_mm;
  stroke.exposed_layer =
      args.exposed_layer < 0 ? kCanvasGround : static_cast<std::uint8_t>(args.exposed_layer);
  stamp_crack(painting, stroke);
  painting.save(args.save);
  print_stats(crack_map_of(painting));
}

struct CavityArgs {
  std::string shape{shape_name(CavityShape::VGroove)};
  double depth_mm = 0.2, half_width_mm = 0.05, rho0 = 0.5;
  CrackSceneLight light;  // the corrected model's light: sun zenith and sky share
};

void run_cavity(const CavityArgs& args) {
  const CavityShape shape = shape_from_name(args.shape);
  if (!(args.rho0 >= 0.0 && args.rho0 <= 1.0)) throw std::runtime_error("--rho0 must be in [0, 1]");
  const ViewFactors vf = view_factors(shape, {args.depth_mm, args.half_width_mm});
  const nlohmann::json out = {
      {"shape", args.shape},
      {"F", vf.F},
      {"G", vf.G},
      {"apparent_reflectance", apparent_reflectance(args.rho0, vf)},
      {"apparent_emissivity", apparent_emissivity(args.rho0, vf)},
      {"corrected_reflectance",
       cavity_reflectance(CavityModel::Corrected, shape, {args.depth_mm, args.half_width_mm}, vf,
                          args.rho0, args.light)},
      {"first_order", apparent_reflectance_first_order(args.rho0, vf)},
      {"second_order", apparent_reflectance_second_order(args.rho0, vf)}};
  std::cout << out.dump() << "\n";
}

struct TableArgs {
  std::string out;
  std::string light = "beam:0";
  std::uint64_t paths = 200000, seed = 1;
};

// Measures the correction table of the Gouffé closed form once, offline (minutes).
void run_table(const TableArgs& args) {
  ProgressReporter progress("cracks table", "traces");
  const CavityTable table = CavityTable::measure(CavityTableGrid{}, parse_cavity_light(args.light),
                                                 args.paths, args.seed, progress.callback());
  progress.finish();
  std::ostringstream out;
  out << "# impasto cracks table --light-geometry " << args.light << " --paths " << args.paths
      << " --seed " << args.seed << "\n";
  table.write_csv(out);
  files::write_file_atomically(args.out, out.str());
}

// These commands always print one JSON object; --json is accepted for scripts that ask.
void add_always_json(CLI::App& cmd) {
  static bool always = true;
  add_json_flag(cmd, always, "always, one object of statistics");
}

const CommandRegistrar registrar("cracks", [](CLI::App& root) {
  CLI::App* group = command_group(root, "cracks", "Cracks and holes as grey-body cavities");

  auto gen = std::make_shared<GenerateArgs>();
  CLI::App* g = group->add_subcommand("generate", "Generate a craquelure crack map");
  add_size_option(*g, gen->size, "for the uniform film (default 1024x1024)");
  add_deprecated_option(*g, "--width", "--size WxH", [gen](const std::string& text) {
    gen->size = CanvasSize{parse_canvas_size(text + "x1", "--width").width,
                           gen->size.value_or(CanvasSize{1024, 1024}).height};
  });
  add_deprecated_option(*g, "--height", "--size WxH", [gen](const std::string& text) {
    gen->size = CanvasSize{gen->size.value_or(CanvasSize{1024, 1024}).width,
                           parse_canvas_size("1x" + text, "--height").height};
  });
  g->add_option("--cell-mm", gen->cell_mm, "Cell size (mm)")->check(CLI::PositiveNumber);
  g->add_option("--thickness-mm", gen->thickness_mm, "Dry paint film thickness (mm)")
      ->check(CLI::NonNegativeNumber);
  g->add_option("--seed", gen->settings.seed, "Random seed");
  g->add_option("--island-mm", gen->settings.island_size_mm, "Mean island size (mm)")
      ->check(CLI::PositiveNumber);
  g->add_option("--age-years", gen->settings.age_years, "Age of the painting (years)")
      ->check(CLI::NonNegativeNumber);
  g->add_option("--jitter", gen->settings.jitter, "Island jitter, 0..1")
      ->check(finite_range(0.0, 1.0));
  add_choice_option(*g, "--shape", gen->shape, kCavityShapeNames,
                    "Crack section (craquelure: a groove)");
  add_out_option(*g, gen->out, "the depths as a 16-bit grey PNG");
  g->add_option("--max-depth-mm", gen->max_depth_mm, "Depth drawn white in --out (mm)")
      ->check(CLI::PositiveNumber);
  g->add_option("--painting", gen->painting,
                "Crack this painting's dry layers (its size and cells; needs --save)");
  g->add_flag("--dry", gen->dry, "Dry the painting's wet paint before cracking it");
  add_save_option(*g, gen->save, "the cracked one (with --painting)");
  add_always_json(*g);
  g->callback([gen] { run_generate(*gen); });

  auto imp = std::make_shared<ImportArgs>();
  CLI::App* i = group->add_subcommand("import", "Read a crack map from a grey PNG (grey = depth)");
  i->add_option("png", imp->png, "PNG file")->required();
  i->add_option("--cell-mm", imp->settings.cell_mm, "Cell size (mm)")->check(CLI::PositiveNumber);
  i->add_option("--max-depth-mm", imp->settings.max_depth_mm, "Depth of white (mm)")
      ->check(CLI::PositiveNumber);
  i->add_option("--depth-to-half-width", imp->settings.depth_to_half_width, "L / R")
      ->check(CLI::PositiveNumber);
  add_choice_option(*i, "--shape", imp->shape, kCavityShapeNames, "Crack section");
  i->add_option("--painting", imp->painting,
                "Put the map into this painting (same size in cells; needs --save)");
  add_save_option(*i, imp->save, "the cracked one (with --painting)");
  add_always_json(*i);
  i->callback([imp] { run_import(*imp); });

  auto brush = std::make_shared<BrushArgs>();
  CLI::App* b = group->add_subcommand("brush", "Draw a crack along a polyline into a painting");
  b->add_option("painting", brush->painting, "The .impasto painting file")->required();
  add_save_option(*b, brush->save, "the cracked one")->required();
  b->add_option("--points", brush->points, "Polyline, \"x,y x,y ...\" in mm")->required();
  add_choice_option(*b, "--shape", brush->shape, kCavityShapeNames, "Crack section");
  b->add_option("--depth-mm", brush->depth_mm, "Depth L (mm)")->check(CLI::PositiveNumber);
  b->add_option("--half-width-mm", brush->half_width_mm, "Half-width R (mm)")
      ->check(CLI::PositiveNumber);
  b->add_option("--exposed-layer", brush->exposed_layer,
                "Dry layer the walls expose (0 = lowest); default: the canvas ground")
      ->check(finite_range(0, 254));
  add_always_json(*b);
  b->callback([brush] { run_brush(*brush); });

  auto cav = std::make_shared<CavityArgs>();
  CLI::App* c = group->add_subcommand("cavity", "F, G and apparent reflectance of one cavity");
  add_choice_option(*c, "--shape", cav->shape, kCavityShapeNames, "Cavity section");
  c->add_option("--depth-mm", cav->depth_mm, "Depth L (mm)")->check(CLI::NonNegativeNumber);
  c->add_option("--half-width-mm", cav->half_width_mm, "Half-width R (mm)")
      ->check(CLI::PositiveNumber);
  c->add_option("--rho0", cav->rho0, "Wall reflectance, 0..1");
  c->add_option("--sun-zenith", cav->light.sun_zenith_deg,
                "Corrected model: the sun's angle from the canvas normal (degrees)")
      ->check(finite_range(0.0, 90.0));
  c->add_option("--sky", cav->light.sky_share, "Corrected model: the sky's share of the light")
      ->check(finite_range(0.0, 1.0));
  add_always_json(*c);
  c->callback([cav] { run_cavity(*cav); });

  auto tab = std::make_shared<TableArgs>();
  CLI::App* t = group->add_subcommand(
      "table", "Measure the Monte Carlo correction table of Gouffé's formula (offline)");
  add_out_option(*t, tab->out, "the table, a CSV (data/cracks/cavity_table*.csv)")->required();
  t->add_option("--paths", tab->paths, "Monte Carlo paths per shape and L/R")
      ->check(finite_range(std::uint64_t{100}, std::uint64_t{100000000}));
  t->add_option("--seed", tab->seed, "Monte Carlo seed");
  t->add_option("--light-geometry", tab->light,
                "beam:ZENITH_DEG (a beam tilted across grooves; data/cracks/"
                "cavity_table_beam_Z.csv) or diffuse (a uniform sky; cavity_table_diffuse.csv)")
      ->capture_default_str();
  // --light is a light's spectrum everywhere else.
  add_deprecated_option(*t, "--light", "--light-geometry",
                        [tab](const std::string& geometry) { tab->light = geometry; });
  t->callback([tab] { run_table(*tab); });
});

}  // namespace
}  // namespace impasto::app::cracks_cmd
