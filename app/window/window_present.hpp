#pragma once
// Puts the window's frames on screen. Where the GL driver can copy part of the back buffer
// to the window (GLX_MESA_copy_sub_buffer, which Mesa's software rasterisers offer), a frame
// presents only the rectangles that changed, and the back buffer, never swapped, keeps the
// last frame for the next one to draw over: a stroke's frame then costs its dirty tiles and
// the status bar instead of every pixel of the window twice (a copy in, a copy out).
// Elsewhere, and after anything that may have lost the window's pixels, a frame is swapped
// whole. IMPASTO_PRESENT=swap forces whole frames (to compare).
#include <span>
#include <vector>

#include <impasto/render_gl/shaded_view_cache.hpp>

struct GLFWwindow;

namespace impasto::app::window {

class WindowPresenter {
 public:
  explicit WindowPresenter(GLFWwindow* window);
  // Whether present_parts() may be used: the back buffer keeps what was drawn into it.
  bool partial() const { return copy_sub_buffer_ != nullptr; }
  // The whole back buffer to the window.
  void present_all();
  // Only these rectangles of the back buffer (GL pixels, origin bottom-left); partial() only.
  void present_parts(std::span<const render_gl::PixelRect> rects);

 private:
  using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width,
                                 int height);
  GLFWwindow* window_;
  void* display_ = nullptr;
  unsigned long drawable_ = 0;
  CopySubBuffer copy_sub_buffer_ = nullptr;
};

// The rectangles to present for a frame, merged into their bounding box when that costs no
// more than drawing them one by one (or when there are many).
std::vector<render_gl::PixelRect> merge_rects(std::vector<render_gl::PixelRect> rects);

}  // namespace impasto::app::window
