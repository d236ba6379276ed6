#pragma once
// What the commands that replay a stroke file (replay, timelapse) take on top of it: a blank
// canvas of another size or dpi, the worker threads and the paint model's constants
// (--param NAME=VALUE, each checked by name).
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/replay.hpp"
#include "vocabulary_words.hpp"

namespace impasto::app {

session::ReplayOptions replay_options(const std::optional<CanvasSize>& size,
                                      const std::optional<double>& dpi, int threads,
                                      const std::vector<std::string>& params);

}  // namespace impasto::app
