#include "replay_overrides.hpp"

namespace impasto::app {

session::ReplayOptions replay_options(const std::optional<CanvasSize>& size,
                                      const std::optional<double>& dpi, int threads,
                                      const std::vector<std::string>& params) {
  session::ReplayOptions options;
  options.dpi = dpi;
  if (size) {
    options.width_cells = size->width;
    options.height_cells = size->height;
  }
  options.threads = threads;
  for (const std::string& assignment : params) paintcore::set_param(options.params, assignment);
  return options;
}

}  // namespace impasto::app
