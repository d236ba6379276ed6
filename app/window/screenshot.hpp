#pragma once
// The whole window (canvas and panels) as a PNG.
#include <filesystem>

namespace impasto::app::window {

// Reads the back buffer of the current GL context (call after drawing, before swapping) and
// writes it as an 8-bit RGB PNG. Throws std::runtime_error naming the file on failure.
void save_window_screenshot(const std::filesystem::path& file, int framebuffer_w,
                            int framebuffer_h);

}  // namespace impasto::app::window
