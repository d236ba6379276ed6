#pragma once
// The reference image (View > Reference image...): a PNG the painter works from, in a window
// of its own beside the canvas. Drag to pan, the wheel zooms about the pointer, a click picks
// the colour under it (a 3 x 3 mean) as the colour target, whose recipes are found at once
// (colour_target.hpp). The image is only looked at: it is not part of the painting.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "window/colour_target.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// An image's pixels as 8-bit sRGB, and its colour at a point: the mean of the pixels of the
// 3 x 3 block around it that lie in the image, taken in linear light and encoded again.
struct ReferencePixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 a pixel, row-major
};
std::array<float, 3> picked_colour(const ReferencePixels& pixels, int x, int y);

class ReferenceImage {
 public:
  ReferenceImage() = default;
  ReferenceImage(const ReferenceImage&) = delete;
  ReferenceImage& operator=(const ReferenceImage&) = delete;
  ~ReferenceImage();  // frees the texture (the GL context is still current)

  // Opens what state.reference_requested names (a notification when it cannot), then draws
  // the window while an image is open; a click picks the colour as `target`'s.
  void draw(WindowState& s, ColourTarget& target);

 private:
  void open(const std::filesystem::path& file, WindowState& s);

  ReferencePixels pixels_;
  unsigned texture_ = 0;
  std::string title_;
  bool open_ = false;
  // The view: image pixels a screen pixel (the zoom's inverse) and the image point at the
  // view's centre; fitted when opened.
  double image_per_screen_ = 1.0;
  std::array<double, 2> centre_{};
  bool fit_ = true;
  bool dragged_ = false;  // the press under way has moved past a click's slop: a pan
};

}  // namespace impasto::app::window
