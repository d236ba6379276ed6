#pragma once
// The corrected cavity model for one scene's light (docs/cracks.md, "The measured correction").
//
// A cavity's apparent reflectance depends on where the light enters it: a beam along the axis
// reaches the bottom and escapes least; a tilted sun lands on the walls near the rim and
// escapes more; a uniform sky lights the rim most. The shipped tables measure the reference
// for beams at several zenith angles and for the sky (cavity_table.hpp). A scene's correction
// blends their differences d = rho_table - rho_Gouffe once per light:
//   d = (1 - s) d_beam(sun zenith) + s d_sky,   s: the sky's share of the irradiance,
// linear between the measured zeniths. A groove's section sees the sun's zenith projected
// onto it, atan(tan(zenith) |cos(azimuth)|); grooves run every way in a crack network, so
// their beam term is the mean over the azimuth. The renderers then look up one table.
#include <memory>
#include <span>
#include <vector>

#include "impasto/cracks/cavity_table.hpp"

namespace impasto::cracks {

// The light a canvas receives, as the far view of its cracks needs it.
struct CrackSceneLight {
  double sun_zenith_deg = 0.0;  // the direct light's angle from the canvas normal, 0..90
  double sky_share = 0.0;       // share of the irradiance from a uniform sky, 0..1
  // On: grooves average the sun's azimuth (a network's grooves run every way). Off: the sun
  // tilts across every groove, as the Monte Carlo reference's beam does (for checks).
  bool average_groove_azimuth = true;

  bool operator==(const CrackSceneLight&) const = default;
};

class CavityCorrection {
 public:
  // Blends the shipped tables for this light.
  explicit CavityCorrection(const CrackSceneLight& light);

  const CrackSceneLight& light() const { return light_; }
  const CavityTableGrid& grid() const { return grid_; }
  // d per [shape][L/R][rho0], as CavityTable::differences.
  const std::vector<float>& differences() const { return differences_; }
  double ratio_coordinate(double depth_over_half_width) const {
    return shipped_cavity_table().ratio_coordinate(depth_over_half_width);
  }
  // The corrected reflectance, clamped to [0, rho0]; u from ratio_coordinate.
  double reflectance_at(CavityShape shape, double u, const ViewFactors& vf, double rho0) const;

 private:
  CrackSceneLight light_;
  CavityTableGrid grid_;
  std::vector<float> differences_;
};

// The correction for a light, blended once per distinct light and shared (thread-safe).
std::shared_ptr<const CavityCorrection> cavity_correction(const CrackSceneLight& light);

// Apparent reflectance of a cavity of the given view factors under either model; the closed
// form does not depend on the light.
double cavity_reflectance(CavityModel model, CavityShape shape, const CavityDims& dims,
                          const ViewFactors& vf, double rho0, const CrackSceneLight& light = {});

}  // namespace impasto::cracks
