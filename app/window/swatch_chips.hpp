#pragma once
// The Palette panel's colour chips, kept up to date off the UI thread: the swatch of the
// mix (session/swatch.hpp: the standard stroke as rendered, and the masstone) and, per
// pigment of the database, its masstone and a layer as thick as the swatch's deposit.
#include <impasto/paintcore/canvas.hpp>
#include <impasto/render/spectral_sampling.hpp>

#include <future>
#include <optional>

#include "impasto/session/swatch.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class SwatchChips {
 public:
  SwatchChips() = default;
  SwatchChips(const SwatchChips&) = delete;
  SwatchChips& operator=(const SwatchChips&) = delete;
  ~SwatchChips();  // waits for a computation in flight

  // Takes a finished computation into `state`, and starts the next one when the brush, the
  // load, the pressure, the canvas, the painting's rule or (state.mix_changed) the light differ
  // from the last. The chips are rendered with `rule`, the painting's own (CanvasViewer's
  // palette), so they show each paint as the canvas shows it. Never blocks.
  void update(WindowState& state, const paintcore::CanvasSpec& canvas,
              const render::SpectralSampling& rule);

 private:
  struct Result {
    std::optional<session::Swatch> swatch;  // none for an empty mix
    std::vector<session::DisplayRgb> pigment_masstones, pigment_layers, pigment_glazes;
  };
  static Result compute(const session::SwatchStroke& stroke, const render::RenderSettings& settings,
                        double layer_mm, const render::SpectralSampling& rule);

  std::future<Result> job_;
  std::optional<session::SwatchStroke> started_;  // the stroke of the job in flight or last done
  render::SpectralSampling started_rule_;         // and its rule
};

}  // namespace impasto::app::window
