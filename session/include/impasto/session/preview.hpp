#pragma once
// A quick false-colour view of a painting's paint, with no spectral data: every pigment slot
// gets a fixed hue, cells show the volume-weighted mix of the paint on top, shaded by the
// relief. For checking the simulation; `impasto render` shows true colour.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/image.hpp>

namespace impasto::session {

// The display colour (sRGB, 0..1) that the preview gives pigment slot `slot`.
void preview_slot_color(int slot, float rgb[3]);

render::Image render_preview(const paintcore::Painting& painting);

}  // namespace impasto::session
