#include "window/window_title.hpp"

namespace impasto::app::window {

std::string window_title(const std::optional<std::filesystem::path>& painting, bool unsaved) {
  const std::string name = painting ? painting->filename().string() : std::string("Untitled");
  return (unsaved ? "\u2022 " : "") + name + " \u2014 Impasto";
}

}  // namespace impasto::app::window
