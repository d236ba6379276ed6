// impasto pigments: list and show the pigment database; fit K and S from measurements.
#include <impasto/data/data_dir.hpp>
#include <impasto/data/ks_fit.hpp>
#include <impasto/data/kubelka_munk.hpp>
#include <impasto/data/pigments.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "command.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::pigments_cmd {
namespace {

using namespace impasto::data;

// The shipped database, or the folder given with --pigments.
PigmentDatabase open_database(const std::string& folder) {
  return PigmentDatabase::load(folder.empty() ? data_dir() / "pigments"
                                              : std::filesystem::path(folder));
}

void run_list(const std::string& folder) {
  const PigmentDatabase db = open_database(folder);
  for (const Pigment& p : db.all()) {
    const auto binder = p.metadata.find("binder");
    std::printf("%-32s %4.0f-%4.0f nm  %s\n", p.name.c_str(), p.K.wavelengths_nm.front(),
                p.K.wavelengths_nm.back(),
                binder == p.metadata.end() ? "" : binder->second.c_str());
  }
}

void run_show(const std::string& folder, const std::string& name) {
  const PigmentDatabase db = open_database(folder);
  const Pigment& p = db.get(name);
  std::printf("name: %s\n", p.name.c_str());
  for (const auto& [key, value] : p.metadata) {
    if (key != "name") std::printf("%s: %s\n", key.c_str(), value.c_str());
  }
  std::printf("%8s %12s %12s %12s %10s\n", "nm", "K", "S", "K/S", "R_inf");
  for (std::size_t i = 0; i < p.K.wavelengths_nm.size(); ++i) {
    const double nm = p.K.wavelengths_nm[i];
    const double k = p.K.values[i], s = p.S.at(nm);
    const double ks = s > 0 ? k / s : HUGE_VAL;
    std::printf("%8.1f %12.6g %12.6g %12.6g %10.6f\n", nm, k, s, ks,
                s > 0 ? reflectance_from_ks(ks) : 0.0);
  }
}

struct FitArgs {
  std::string measurements;
  std::string out;
  std::string reference;
};

void run_fit(const FitArgs& args) {
  KsFitProblem problem = read_ks_measurements(args.measurements);
  if (!args.reference.empty()) problem.reference_pigment = args.reference;
  const KsFitResult fit = fit_kubelka_munk(problem);

  std::filesystem::create_directories(args.out);
  for (Pigment pigment : fit.pigments) {
    pigment.metadata["source"] = "fitted by impasto pigments fit from " +
                                 std::filesystem::path(args.measurements).filename().string();
    pigment.metadata["units"] = "K and S relative to the S of " + problem.reference_pigment;
    if (problem.saunderson) {
      char text[96];
      std::snprintf(text, sizeof text, "Saunderson k1 %g, k2 %g removed before fitting",
                    problem.saunderson->k1, problem.saunderson->k2);
      pigment.metadata["interface"] = text;
    }
    const auto path = std::filesystem::path(args.out) / pigment_file_name(pigment.name);
    write_pigment_file(path, pigment);
    std::printf("wrote %s\n", path.string().c_str());
  }
  std::printf("%-32s %14s %14s %14s\n", "sample", "rms K/S eq.", "rms R", "max |dR|");
  for (const KsSampleResidual& r : fit.residuals) {
    std::printf("%-32s %14.6g %14.6g %14.6g\n", r.name.c_str(), r.rms_equation, r.rms_reflectance,
                r.max_reflectance);
  }
}

const CommandRegistrar registrar("pigments", [](CLI::App& root) {
  CLI::App* group = command_group(root, "pigments", "The pigment database and the K/S fit");
  auto folder = std::make_shared<std::string>();
  group->add_option("--pigments", *folder, "Pigment folder (default: the shipped database)");

  group->add_subcommand("list", "List the pigments")->callback([folder] { run_list(*folder); });

  auto name = std::make_shared<std::string>();
  CLI::App* show = group->add_subcommand("show", "Show one pigment's metadata and K, S");
  show->add_option("name", *name, "Pigment name (case-insensitive)")->required();
  show->callback([folder, name] { run_show(*folder, *name); });

  auto fit = std::make_shared<FitArgs>();
  CLI::App* f = group->add_subcommand(
      "fit", "Fit K and S from measured reflectances of masstones and mixtures");
  f->add_option("measurements", fit->measurements, "Measurements CSV (docs/pigments.md)")
      ->required();
  f->add_option("--out", fit->out, "Folder for the fitted pigment files")->required();
  f->add_option("--reference", fit->reference,
                "Pigment whose S is fixed to 1 (overrides '# reference:')");
  f->callback([fit] { run_fit(*fit); });
});

}  // namespace
}  // namespace impasto::app::pigments_cmd
