#pragma once
// The Surface panel: how the paint's surface reflects (docs/surface.md): the model (blinn or
// ghs), the medium's finish and its amount, a varnish over the whole painting and the
// subsurface spread, by the names of `impasto render --surface/--medium/--medium-amount/
// --varnish/--no-subsurface`, and the spread's map (GpuViewOptions::subsurface_map). A change
// rebuilds the surface's tables and re-shades the canvas (WindowState::settings_changed), so the
// view is a live preview.
#include <impasto/render/surface_settings.hpp>

#include <optional>
#include <string>
#include <vector>

#include "window/window_state.hpp"

namespace impasto::app::window {

// The varnish choices as the command line spells them: "none", then each finish.
std::vector<std::string> varnish_names();
// The position of a varnish in varnish_names(), and back (out of range: none).
int varnish_index(const std::optional<render::surface::Finish>& varnish);
std::optional<render::surface::Finish> varnish_at(int index);

void surface_panel(WindowState& state);

}  // namespace impasto::app::window
