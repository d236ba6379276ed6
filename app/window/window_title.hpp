#pragma once
// The painting window's title: "• name.impasto — Impasto" while the painting has unsaved
// changes, "name.impasto — Impasto" once saved, "Untitled — Impasto" before it has a file.
// (Scripts find the window by the title's end, "Impasto".)
#include <filesystem>
#include <optional>
#include <string>

namespace impasto::app::window {

std::string window_title(const std::optional<std::filesystem::path>& painting, bool unsaved);

}  // namespace impasto::app::window
