// impasto color: colorimetry of spectral CSV files (XYZ and L*a*b* under a light), and the
// recipe of pigments that comes nearest a colour.
#include <impasto/data/colorimetry.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/data/spectral_csv.hpp>
#include <impasto/render/colour_recipe.hpp>

#include <array>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::color_cmd {
namespace {

using namespace impasto::data;

struct XyzArgs {
  std::string file;
  std::string illuminant = "D65";
  bool json = false;
};

void run_xyz(const XyzArgs& args) {
  const SpectralTable table = read_spectral_csv(args.file);
  if (table.quantity != SpectralQuantity::reflectance &&
      table.quantity != SpectralQuantity::transmittance &&
      table.quantity != SpectralQuantity::unspecified) {
    throw std::runtime_error(args.file + ": expected reflectance or transmittance, not " +
                             std::string(to_string(table.quantity)));
  }
  const Spectrum light = light_from_spec(args.illuminant);
  const Xyz white = white_point(light);
  nlohmann::json out = {{"illuminant", light.name},
                        {"observer", "CIE 1931 2 degree"},
                        {"white", {white.X, white.Y, white.Z}},
                        {"samples", nlohmann::json::array()}};
  if (!args.json) {
    std::printf("illuminant %s, CIE 1931 2° observer, white X Y Z = %.4f %.4f %.4f\n",
                light.name.c_str(), white.X, white.Y, white.Z);
    std::printf("%-24s %9s %9s %9s %9s %9s %9s\n", "sample", "X", "Y", "Z", "L*", "a*", "b*");
  }
  for (const Spectrum& column : table.columns) {
    const Xyz xyz = reflectance_to_xyz(column, light);
    const Lab lab = xyz_to_lab(xyz, white);
    if (args.json) {
      out["samples"].push_back(
          {{"name", column.name}, {"XYZ", {xyz.X, xyz.Y, xyz.Z}}, {"Lab", {lab.L, lab.a, lab.b}}});
    } else {
      std::printf("%-24s %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f\n", column.name.c_str(), xyz.X, xyz.Y,
                  xyz.Z, lab.L, lab.a, lab.b);
    }
  }
  if (args.json) std::cout << out.dump(2) << "\n";
}

struct RecipeArgs {
  std::string colour;
  std::string light = "D65";
  bool json = false;
};

void run_recipe(const RecipeArgs& args) {
  const std::array<double, 3> srgb = render::parse_srgb_colour(args.colour);
  const data::Lab target = render::srgb_to_lab(srgb);
  const std::vector<Pigment>& palette = PigmentDatabase::defaults().all();
  const render::RecipeFinder finder(palette, light_from_spec(args.light));
  const std::vector<render::Recipe> recipes = finder.find(target);
  nlohmann::json out = {{"target", {{"srgb", srgb}, {"Lab", {target.L, target.a, target.b}}}},
                        {"light", args.light},
                        {"recipes", nlohmann::json::array()}};
  if (!args.json)
    std::printf("target %s: L*a*b* %.1f %.1f %.1f; masstones under %s\n", args.colour.c_str(),
                target.L, target.a, target.b, args.light.c_str());
  for (const render::Recipe& recipe : recipes) {
    nlohmann::json parts = nlohmann::json::array();
    std::string text;
    for (const render::RecipePart& part : recipe.parts) {
      parts.push_back({{"pigment", palette[part.pigment].name}, {"share", part.share}});
      char share[64];
      std::snprintf(share, sizeof share, "%s%.0f%% ", text.empty() ? "" : "+ ", 100 * part.share);
      text += share + palette[part.pigment].name + " ";
    }
    out["recipes"].push_back({{"parts", parts},
                              {"delta_e00", recipe.delta_e00},
                              {"Lab", {recipe.lab.L, recipe.lab.a, recipe.lab.b}},
                              {"srgb", recipe.srgb}});
    if (!args.json) std::printf("  dE00 %5.2f  %s\n", recipe.delta_e00, text.c_str());
  }
  if (args.json) std::cout << out.dump(2) << "\n";
}

const CommandRegistrar registrar("color", [](CLI::App& root) {
  CLI::App* group = command_group(root, "color", "Colorimetry of spectral CSV files");

  auto xyz = std::make_shared<XyzArgs>();
  CLI::App* x =
      group->add_subcommand("xyz", "X, Y, Z (white Y = 100) and L*a*b* of each reflectance column");
  x->add_option("spectrum", xyz->file, "Spectral CSV (docs/spectral-csv.md)")->required();
  x->add_option("--light", xyz->illuminant, vocabulary_help("--light"))->capture_default_str();
  add_json_flag(*x, xyz->json, "the light, its white and each column's XYZ and L*a*b*");
  for (const char* old : {"--illuminant", "-i"})
    add_deprecated_option(*x, old, "--light",
                          [xyz](const std::string& light) { xyz->illuminant = light; });
  x->callback([xyz] { run_xyz(*xyz); });

  auto recipe = std::make_shared<RecipeArgs>();
  CLI::App* r = group->add_subcommand(
      "recipe",
      "The pigments whose masstone comes nearest a colour (the best of one, two and three, "
      "with their CIEDE2000)");
  r->add_option("colour", recipe->colour, "The target, #RRGGBB or R,G,B (0-255), as sRGB")
      ->required();
  r->add_option("--light", recipe->light, vocabulary_help("--light"))->capture_default_str();
  add_json_flag(*r, recipe->json, "the target and each recipe's parts, CIEDE2000, L*a*b*, sRGB");
  r->callback([recipe] { run_recipe(*recipe); });

  CLI::App* lights = group->add_subcommand("illuminants", "List the CIE illuminants shipped");
  lights->callback([] {
    for (const auto& name : illuminant_names()) {
      const Xyz white = white_point(cie_illuminant(name));
      const Chromaticity xy = chromaticity(white);
      std::printf("%-4s x = %.4f  y = %.4f\n", name.c_str(), xy.x, xy.y);
    }
  });
});

}  // namespace
}  // namespace impasto::app::color_cmd
