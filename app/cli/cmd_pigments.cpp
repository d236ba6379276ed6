// impasto pigments: the layered pigment library (list, show, check) and the K/S fit.
#include <impasto/data/colorimetry.hpp>
#include <impasto/data/data_dir.hpp>
#include <impasto/data/ks_fit.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigment_library.hpp>
#include <impasto/data/pigment_user_layer.hpp>
#include <impasto/data/pigments.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "command.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"
#include "pigment_curves.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::pigments_cmd {
namespace {

using namespace impasto::data;

// A metadata field in a few words, for a table: up to its first ',', '(', ':' or ';' ("CC BY
// 4.0" of "CC BY 4.0 (credit: ...)"), or "-".
std::string field_in_brief(const Pigment& p, const std::string& key) {
  const auto found = p.metadata.find(key);
  if (found == p.metadata.end() || found->second.empty()) return "-";
  return std::string(util::trim(found->second.substr(0, found->second.find_first_of(",(:;"))));
}

void run_list(bool json) {
  const PigmentLibrary& library = active_pigment_library();
  const auto& all = library.database().all();
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Pigment& p = all[i];
    const auto binder = p.metadata.find("binder");
    if (json) {
      rows.push_back({{"name", p.name},
                      {"from_nm", p.K.wavelengths_nm.front()},
                      {"to_nm", p.K.wavelengths_nm.back()},
                      {"layer", library.origins()[i].layer},
                      {"file", library.origins()[i].file.string()},
                      {"binder", binder == p.metadata.end() ? "" : binder->second},
                      {"licence", p.metadata.contains("licence") ? p.metadata.at("licence") : ""},
                      {"source", p.metadata.contains("source") ? p.metadata.at("source") : ""}});
      continue;
    }
    std::printf("%-26s %4.0f-%4.0f nm  %-8s %-16s %-8s %s\n", files::terminal_text(p.name).c_str(),
                p.K.wavelengths_nm.front(), p.K.wavelengths_nm.back(),
                library.origins()[i].layer.c_str(),
                files::terminal_text(field_in_brief(p, "licence")).c_str(),
                files::terminal_text(binder == p.metadata.end() ? "" : binder->second).c_str(),
                files::terminal_text(field_in_brief(p, "source")).c_str());
  }
  if (json) std::cout << rows.dump(2) << "\n";
}

void run_show(const std::string& name, bool json) {
  const PigmentLibrary& library = active_pigment_library();
  const Pigment& p = library.database().get(name);
  if (json) {
    const LibraryPigment* origin = library.origin(p.name);
    nlohmann::json out{{"name", p.name},
                       {"layer", origin->layer},
                       {"file", origin->file.string()},
                       {"metadata", p.metadata},
                       {"nm", p.K.wavelengths_nm},
                       {"K", p.K.values},
                       {"S", nlohmann::json::array()}};
    out["metadata"].erase("name");
    for (const double nm : p.K.wavelengths_nm) out["S"].push_back(p.S.at(nm));
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::printf("name: %s\n", p.name.c_str());
  const LibraryPigment* origin = library.origin(p.name);
  std::printf("layer: %s (%s)\n", origin->layer.c_str(), origin->file.string().c_str());
  for (const auto& [key, value] : p.metadata) {
    if (key != "name") std::printf("%s: %s\n", key.c_str(), value.c_str());
  }
  std::printf("%8s %12s %12s %12s %10s\n", "nm", "K", "S", "K/S", "R_inf");
  const PigmentCurves c = pigment_curves(p);
  for (std::size_t i = 0; i < c.nm.size(); ++i) {
    std::printf("%8.1f %12.6g %12.6g %12.6g %10.6f\n", c.nm[i], c.k[i], c.s[i], c.k_over_s[i],
                c.r_infinite[i]);
  }
}

// Every problem of a folder at once; fails the command when there is any.
void run_check(const std::string& folder, bool json) {
  if (!std::filesystem::is_directory(folder)) throw std::runtime_error(folder + ": not a folder");
  const PigmentFolderScan scan = scan_pigment_folder(folder);
  if (json) {
    nlohmann::json out{
        {"folder", folder}, {"pigments", nlohmann::json::array()}, {"errors", scan.problems}};
    for (const auto& loaded : scan.pigments)
      out["pigments"].push_back(
          {{"file", loaded.file.filename().string()}, {"name", loaded.pigment.name}});
    std::cout << out.dump(2) << "\n";
  } else {
    for (const auto& loaded : scan.pigments)
      std::printf("ok      %s (%s)\n", loaded.file.filename().string().c_str(),
                  loaded.pigment.name.c_str());
    for (const auto& problem : scan.problems) std::printf("error   %s\n", problem.c_str());
    std::printf("%zu pigments load, %zu files have errors\n", scan.pigments.size(),
                scan.problems.size());
  }
  if (!scan.problems.empty())
    throw std::runtime_error(folder + ": " + std::to_string(scan.problems.size()) +
                             " files have errors");
}

struct FitArgs {
  std::string measurements;
  std::string out;
  std::string reference;
  bool force = false;
};

// Metadata a fit keeps from the pigment it replaces (the file in --out, else the library's).
std::map<std::string, std::string> kept_metadata(const std::filesystem::path& file,
                                                 const std::string& name) {
  std::map<std::string, std::string> metadata;
  try {
    if (std::filesystem::exists(file)) {
      metadata = read_pigment_file(file).metadata;
    } else if (const Pigment* p = active_pigment_library().database().find(name)) {
      metadata = p->metadata;
    }
  } catch (const std::exception&) {
  }
  for (const char* derived : {"quantity", "name", "units", "interface", "fitted_from", "modified"})
    metadata.erase(derived);
  return metadata;
}

void run_fit(const FitArgs& args) {
  KsFitProblem problem = read_ks_measurements(args.measurements);
  if (!args.reference.empty()) problem.reference_pigment = args.reference;
  const KsFitResult fit = fit_kubelka_munk(problem);
  const std::filesystem::path out =
      args.out.empty() ? active_pigment_library().user_folder() : std::filesystem::path(args.out);
  if (out.empty()) throw std::runtime_error("no user pigment folder (HOME unset): give --out");

  // Nothing is written unless everything may be.
  for (const Pigment& pigment : fit.pigments) {
    const auto path = out / pigment_file_name(pigment.name);
    if (std::filesystem::exists(path) && !args.force)
      throw std::runtime_error(path.string() +
                               " exists (use --force to replace it; its "
                               "metadata is kept)");
  }
  const std::string from = std::filesystem::path(args.measurements).filename().string();
  for (Pigment pigment : fit.pigments) {
    const auto path = out / pigment_file_name(pigment.name);
    pigment.metadata = kept_metadata(path, pigment.name);
    if (!pigment.metadata.count("source"))
      pigment.metadata["source"] = "fitted by impasto pigments fit";
    pigment.metadata["fitted_from"] = from + " (" + utc_timestamp() + ")";
    pigment.metadata["units"] = "K and S relative to the S of " + problem.reference_pigment;
    if (problem.saunderson) {
      char text[128];
      std::snprintf(text, sizeof text,
                    "Saunderson k1 %g, k2 %g removed before fitting (the instrument read %g of k1)",
                    problem.saunderson->k1, problem.saunderson->k2,
                    problem.saunderson->surface_seen);
      pigment.metadata["interface"] = text;
    }
    note("wrote " + save_pigment_to_folder(out, std::move(pigment), args.force).string());
  }
  const Spectrum d65 = light_from_spec("D65");
  std::vector<const Pigment*> fitted;
  for (const Pigment& p : fit.pigments) fitted.push_back(&p);
  std::printf("%-32s %10s %12s %12s %12s\n", "sample", "dE00 D65", "rms K/S eq.", "rms R",
              "max |dR|");
  for (std::size_t i = 0; i < fit.residuals.size(); ++i) {
    const KsSampleResidual& r = fit.residuals[i];
    const KsSample& sample = problem.samples[i];
    const double de = reflectance_delta_e(
        sample.reflectance, mixture_reflectance(fitted, sample.concentrations, problem.saunderson),
        d65);
    std::printf("%-32s %10.3f %12.6g %12.6g %12.6g\n", r.name.c_str(), de, r.rms_equation,
                r.rms_reflectance, r.max_reflectance);
  }
}

const CommandRegistrar registrar("pigments", [](CLI::App& root) {
  CLI::App* group = command_group(
      root, "pigments", "The pigment library (bundled, user, --pigments) and the K/S fit");

  auto list_json = std::make_shared<bool>(false);
  CLI::App* list = group->add_subcommand("list", "List the pigments and the layer each comes from");
  add_json_flag(*list, *list_json, "name, range, layer, file and binder of each pigment");
  list->callback([list_json] { run_list(*list_json); });

  auto name = std::make_shared<std::string>();
  CLI::App* show = group->add_subcommand("show", "Show one pigment's metadata and K, S");
  show->add_option("name", *name, "Pigment name (case-insensitive)")->required();
  auto show_json = std::make_shared<bool>(false);
  add_json_flag(*show, *show_json, "its metadata and K, S at K's wavelengths");
  show->callback([name, show_json] { run_show(*name, *show_json); });

  auto folder = std::make_shared<std::string>();
  CLI::App* check =
      group->add_subcommand("check", "Validate a pigment folder: every error at once");
  check->add_option("folder", *folder, "Folder of pigment CSVs")->required();
  auto check_json = std::make_shared<bool>(false);
  add_json_flag(*check, *check_json,
                "the pigments that load and every error (exit status 1 "
                "when there is any)");
  check->callback([folder, check_json] { run_check(*folder, *check_json); });

  auto fit = std::make_shared<FitArgs>();
  CLI::App* f = group->add_subcommand(
      "fit", "Fit K and S from measured reflectances of masstones and mixtures");
  f->add_option("measurements", fit->measurements, "Measurements CSV (docs/pigments.md)")
      ->required();
  add_out_option(*f, fit->out, "the folder for the fitted pigment files (default: the user layer)");
  f->add_option("--reference", fit->reference,
                "Pigment whose S is fixed to 1 (overrides '# reference:')");
  f->add_flag("--force", fit->force, "Replace existing files (their metadata is kept)");
  f->callback([fit] { run_fit(*fit); });
});

}  // namespace
}  // namespace impasto::app::pigments_cmd
