// impasto pigments import/add/rename/remove/export (the user layer) and plot/swatch (any
// pigment of the library).
#include <impasto/data/lights.hpp>
#include <impasto/data/pigment_library.hpp>
#include <impasto/data/pigment_user_layer.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/data/spectral_csv.hpp>
#include <impasto/render/pigment_swatches.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "pigment_figure.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::pigments_edit_cmd {
namespace {

using namespace impasto::data;

std::filesystem::path user_folder() {
  const std::filesystem::path folder = active_pigment_library().user_folder();
  if (folder.empty())
    throw std::runtime_error("no user pigment folder (set HOME or XDG_DATA_HOME)");
  return folder;
}

struct EditArgs {
  std::string file, name, new_name, copy_of, out, tint, light = "D65";
  std::vector<std::string> set;
  double k = -1, s = -1;
  bool force = false;
  bool json = false;
};

void run_import(const EditArgs& a) {
  const auto path = import_pigment_file(user_folder(), a.file, a.force);
  note("imported " + a.file + " into the user layer: " + path.string());
}

// KEY=VALUE pairs into metadata.
void apply_settings(Pigment& pigment, const std::vector<std::string>& settings) {
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::runtime_error("--set " + setting + ": expected KEY=VALUE");
    const std::string key = setting.substr(0, eq);
    if (key == "name" || key == "quantity" || key == "flakes")
      throw std::runtime_error("--set: '" + key + "' is not metadata one sets by hand");
    pigment.metadata[key] = setting.substr(eq + 1);
  }
}

void run_add(const EditArgs& a) {
  Pigment pigment;
  if (!a.copy_of.empty()) {
    pigment = active_pigment_library().database().get(a.copy_of);
    pigment.metadata["modified"] = utc_timestamp() + " copied from " + pigment.name;
  } else if (a.k >= 0 && a.s >= 0) {
    pigment.K = {"K", {380, 730}, {a.k, a.k}};
    pigment.S = {"S", {380, 730}, {a.s, a.s}};
    pigment.metadata["modified"] = utc_timestamp() + " flat K and S";
  } else {
    throw std::runtime_error("add: give --copy-of PIGMENT, or --k and --s (flat spectra)");
  }
  pigment.name = a.name;
  apply_settings(pigment, a.set);
  const auto path = save_pigment_to_folder(user_folder(), std::move(pigment), a.force);
  note("added " + a.name + ": " + path.string());
}

void run_rename(const EditArgs& a) {
  const auto path = rename_pigment_in_folder(user_folder(), a.name, a.new_name);
  note("renamed " + a.name + " to " + a.new_name + ": " + path.string());
}

void run_remove(const EditArgs& a) {
  note("removed " + remove_pigment_from_folder(user_folder(), a.name).string());
}

void run_export(const EditArgs& a) {
  const Pigment& pigment = active_pigment_library().database().get(a.name);
  const std::filesystem::path out = a.out;
  if (std::filesystem::exists(out) && !a.force)
    throw std::runtime_error(out.string() + " exists (use --force to replace it)");
  Pigment copy = pigment;
  copy.metadata.erase("flakes");  // a flake file is copied by save_pigment_to_folder, not here
  if (!pigment.flakes.empty())
    copy.metadata["flakes"] = pigment.metadata.at("flakes");  // as it was, relative
  write_pigment_file(out, copy);
  note("exported " + pigment.name + ": " + out.string());
}

const Pigment& white_of(const PigmentDatabase& db) {
  return db.get("White");
}

void run_plot(const EditArgs& a) {
  const PigmentLibrary& library = active_pigment_library();
  const Pigment& pigment = library.database().get(a.name);
  std::string subtitle = library.origin(pigment.name)->layer + " layer";
  if (auto ci = pigment.metadata.find("colour_index"); ci != pigment.metadata.end())
    subtitle = ci->second + ", " + subtitle;
  write_figure(a.out, pigment_figure(pigment, subtitle, white_of(library.database()),
                                     light_from_spec(a.light), a.light));
  note("wrote " + a.out);
}

// "1:4" -> 4 parts of white to 1 of the pigment.
double tint_parts(const std::string& tint) {
  const auto colon = tint.find(':');
  try {
    if (colon != std::string::npos && tint.substr(0, colon) == "1") {
      std::size_t used = 0;
      const double parts = std::stod(tint.substr(colon + 1), &used);
      if (used == tint.size() - colon - 1 && parts >= 0 && parts <= 1e6) return parts;
    }
  } catch (const std::exception&) {
  }
  throw std::runtime_error("--tint " + tint + ": expected 1:N (N parts of white, 0..1e6)");
}

void run_swatch(const EditArgs& a) {
  const PigmentDatabase& db = active_pigment_library().database();
  const Pigment& pigment = db.get(a.name);
  const Spectrum light = light_from_spec(a.light);
  std::vector<render::SwatchColour> colours;
  if (a.tint.empty()) {
    colours = render::standard_swatches(pigment, white_of(db), light);
  } else {
    const render::SpectralSampling sampling = render::swatch_sampling(light);
    colours.push_back(
        render::describe_colour("tint " + a.tint,
                                render::seen_through_surface(render::tint_reflectance(
                                    pigment, white_of(db), tint_parts(a.tint), sampling)),
                                sampling));
  }
  if (a.json) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& c : colours)
      rows.push_back({{"swatch", c.label},
                      {"XYZ", {c.xyz.X, c.xyz.Y, c.xyz.Z}},
                      {"Lab", {c.lab.L, c.lab.a, c.lab.b}},
                      {"sRGB", {c.srgb[0], c.srgb[1], c.srgb[2]}}});
    std::cout
        << nlohmann::json{{"pigment", pigment.name}, {"light", a.light}, {"swatches", rows}}.dump(2)
        << "\n";
    return;
  }
  std::printf("%s under %s (L*a*b* relative to the light's white; sRGB adapted to D65)\n",
              pigment.name.c_str(), a.light.c_str());
  std::printf("%-18s %8s %8s %8s %8s %8s %8s  %s\n", "swatch", "X", "Y", "Z", "L*", "a*", "b*",
              "sRGB");
  for (const auto& c : colours) {
    std::printf("%-18s %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f  #%02x%02x%02x\n", c.label.c_str(),
                c.xyz.X, c.xyz.Y, c.xyz.Z, c.lab.L, c.lab.a, c.lab.b,
                int(std::lround(c.srgb[0] * 255)), int(std::lround(c.srgb[1] * 255)),
                int(std::lround(c.srgb[2] * 255)));
  }
}

const CommandRegistrar registrar("pigments edit", [](CLI::App& root) {
  CLI::App* group = command_group(root, "pigments", "The pigment library and the K/S fit");
  auto a = std::make_shared<EditArgs>();

  CLI::App* imp = group->add_subcommand("import", "Copy a pigment CSV into the user layer");
  imp->add_option("file", a->file, "Pigment CSV (docs/pigments.md)")
      ->required()
      ->check(CLI::ExistingFile);
  imp->add_flag("--force", a->force, "Replace the user layer's file of that name");
  imp->callback([a] { run_import(*a); });

  CLI::App* add = group->add_subcommand("add", "Add a pigment to the user layer");
  add->add_option("name", a->name, "The new pigment's name")->required();
  add->add_option("--copy-of", a->copy_of, "Start from this pigment's K, S and metadata");
  add->add_option("--k", a->k, "Flat K (with --s)")
      ->check(finite_range(0.0, impasto::data::kMaxKubelkaMunk));
  add->add_option("--s", a->s, "Flat S (with --k)")
      ->check(finite_range(0.0, impasto::data::kMaxKubelkaMunk));
  add->add_option("--set", a->set, "Metadata KEY=VALUE (binder, colour_index, licence, ...)");
  add->add_flag("--force", a->force, "Replace the user layer's pigment of that name");
  add->callback([a] { run_add(*a); });

  CLI::App* ren = group->add_subcommand("rename", "Rename a pigment of the user layer");
  ren->add_option("name", a->name, "Pigment name")->required();
  ren->add_option("new_name", a->new_name, "New name")->required();
  ren->callback([a] { run_rename(*a); });

  CLI::App* rem = group->add_subcommand("remove", "Remove a pigment from the user layer");
  rem->add_option("name", a->name, "Pigment name")->required();
  rem->callback([a] { run_remove(*a); });

  CLI::App* exp = group->add_subcommand("export", "Write a pigment of the library to a CSV");
  exp->add_option("name", a->name, "Pigment name")->required();
  add_out_option(*exp, a->out, "the pigment CSV")->required();
  exp->add_flag("--force", a->force, "Replace an existing file");
  exp->callback([a] { run_export(*a); });

  CLI::App* plot = group->add_subcommand("plot", "Plot K, S, K/S, R-infinity and swatches");
  plot->add_option("name", a->name, "Pigment name")->required();
  add_out_option(*plot, a->out, "the figure, FILE.png or FILE.svg")->required();
  plot->add_option("--light", a->light, vocabulary_help("--light", "of the swatches"))
      ->capture_default_str();
  plot->callback([a] { run_plot(*a); });

  CLI::App* sw = group->add_subcommand("swatch", "XYZ, L*a*b* and sRGB of masstone, tints, glazes");
  sw->add_option("name", a->name, "Pigment name")->required();
  sw->add_option("--tint", a->tint, "Only this tint with white, 1:N (1:0 is the masstone)");
  sw->add_option("--light", a->light, vocabulary_help("--light"))->capture_default_str();
  add_json_flag(*sw, a->json, "XYZ, L*a*b* and sRGB (0..1, adapted to D65) of each swatch");
  sw->callback([a] { run_swatch(*a); });
});

}  // namespace
}  // namespace impasto::app::pigments_edit_cmd
