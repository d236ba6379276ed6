#pragma once
// The Pigment editor's Fit tab: K and S fitted from a measurement set (data/ks_fit.hpp, the
// NNLS fit), a table per sample with ΔE00 (D65) and reflectance RMS, measured against fitted
// reflectance plotted for the chosen sample, and "save to my library".
#include <impasto/data/ks_fit.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impasto::app::window {

class PigmentFitPanel {
 public:
  // save(pigments, overwrite) writes them to the user layer (the editor's change()).
  void draw(const std::function<void(const std::vector<data::Pigment>&, bool)>& save);
  // For scripts and tests: fit this measurement file now.
  void fit(const std::string& path);
  // The largest ΔE00 over the samples of the last fit (NaN before one).
  double max_delta_e() const;

 private:
  struct Sample {
    std::string name;
    double delta_e = 0, rms = 0, max_abs = 0;
    data::Spectrum measured, fitted;
  };
  char path_[512] = {};
  std::optional<data::KsFitProblem> problem_;
  std::optional<data::KsFitResult> result_;
  std::vector<Sample> samples_;
  int chosen_ = 0;
  bool overwrite_ = false;
  std::string error_;
};

}  // namespace impasto::app::window
