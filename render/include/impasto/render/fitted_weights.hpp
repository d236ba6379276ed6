#pragma once
// Per-node XYZ weights fitted to a palette's paints.
//
// A Gaussian rule integrates polynomials; K-M reflectances of opaque paint are far from
// polynomial (steep absorption edges), and 8 nodes miss what happens between them. But the
// spectra of one palette are few and correlated: the values at the nodes predict the XYZ of
// the full spectrum much better through weights fitted on those very paints. The fit is a
// ridge regression toward the interpolatory weights, with each sample weighted by
// 1 / (Y + 0.05) (a rough stand-in for lightness, so dark colours count), and a perfect
// white forced exact by a heavy weight.
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

// The training paints: every pigment's masstone (2 mm); every pair at 25/75 and 75/25 (2 mm);
// tints of 1:3 and 1:20 with white; glazes of 0.005 and 0.03 mm over the ground and over
// black (zero reflectance). Thicknesses through thickness_scale_mm.
// Replaces sampling.to_xyz (and white_xyz) by the fitted weights; the nodes stay.
void fit_node_weights(SpectralSampling& sampling, const data::Spectrum& light,
                      const data::ColorMatchingFunctions& cmf, const WavelengthRange& range,
                      const std::vector<data::Pigment>& pigments, const data::Spectrum& ground,
                      double thickness_scale_mm);

}  // namespace impasto::render
