#pragma once
// Kubelka–Munk K and S of pigments from measured reflectances of masstones and mixtures
// (IMPaSTo §5.3). Per wavelength, with C the M×N concentrations and Q_R = diag((1−R)²/2R):
//   minimise ‖[C, −Q_R·C]·[K; S]‖²  subject to K, S >= 0 and S_reference = 1,
// a non-negative least-squares problem once S_reference is moved to the right-hand side.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "impasto/data/kubelka_munk.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"

namespace impasto::data {

// One measured, opaque sample: its reflectance and how much of each pigment it contains.
struct KsSample {
  std::string name;
  Spectrum reflectance;                // 0..1
  std::vector<double> concentrations;  // one per KsFitProblem::pigment_names, >= 0
};

struct KsFitProblem {
  std::vector<std::string> pigment_names;
  std::vector<KsSample> samples;
  std::string reference_pigment;         // its S is fixed to 1 (e.g. a titanium white)
  std::optional<Saunderson> saunderson;  // undo the interface on R before fitting
  std::vector<double> grid_nm;           // empty: the first sample's wavelengths
};

struct KsSampleResidual {
  std::string name;
  double rms_equation = 0;     // RMS over wavelengths of (C·K − Q_R·C·S) for this sample
  double rms_reflectance = 0;  // RMS of (fitted R − measured R), in the measured domain
  double max_reflectance = 0;  // largest |fitted R − measured R|
};

struct KsFitResult {
  std::vector<Pigment> pigments;  // in pigment_names order, on the fit's grid
  std::vector<KsSampleResidual> residuals;
};

// Fits K and S; throws std::runtime_error naming the problem (sizes, unknown reference,
// a pigment that no sample contains, reflectance out of range).
KsFitResult fit_kubelka_munk(const KsFitProblem& problem);

// The reflectance an opaque mixture of these pigments would have (measured domain when
// saunderson is given), on the pigments' K grid.
Spectrum mixture_reflectance(const std::vector<const Pigment*>& pigments,
                             const std::vector<double>& concentrations,
                             const std::optional<Saunderson>& saunderson = std::nullopt);

// Reads a measurements CSV (docs/pigments.md): '# quantity: reflectance', one column per
// sample, '# mix SAMPLE: Pigment A=0.25; Pigment B=0.75' for each column,
// '# reference: PIGMENT', optional '# saunderson: K1 K2' and '# surface_seen: SHARE' (the
// share of k1 the instrument read, default 1). Errors name file and line.
KsFitProblem read_ks_measurements(const std::filesystem::path& path);

}  // namespace impasto::data
