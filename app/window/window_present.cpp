#include "window/window_present.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace impasto::app::window {
namespace {

// GLFW's X11 accessors, looked up at run time: a GLFW built without X11 has none, and the
// window then swaps whole frames.
template <typename F>
F glfw_native(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

WindowPresenter::WindowPresenter(GLFWwindow* window) : window_(window) {
  const char* forced = std::getenv("IMPASTO_PRESENT");
  if (forced && std::strcmp(forced, "swap") == 0) return;
  if (!glfwExtensionSupported("GLX_MESA_copy_sub_buffer")) return;
  const auto get_display = glfw_native<void* (*)()>("glfwGetX11Display");
  const auto get_drawable = glfw_native<unsigned long (*)(GLFWwindow*)>("glfwGetGLXWindow");
  if (!get_display || !get_drawable) return;
  display_ = get_display();
  drawable_ = get_drawable(window_);
  if (!display_ || !drawable_) return;
  copy_sub_buffer_ = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
}

void WindowPresenter::present_all() {
  if (!copy_sub_buffer_) {
    glfwSwapBuffers(window_);
    return;
  }
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  copy_sub_buffer_(display_, drawable_, 0, 0, w, h);
}

void WindowPresenter::present_parts(std::span<const render_gl::PixelRect> rects) {
  for (const render_gl::PixelRect& r : rects) {
    if (!r.empty()) copy_sub_buffer_(display_, drawable_, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
  }
}

std::vector<render_gl::PixelRect> merge_rects(std::vector<render_gl::PixelRect> rects) {
  std::erase_if(rects, [](const render_gl::PixelRect& r) { return r.empty(); });
  if (rects.size() < 2) return rects;
  render_gl::PixelRect box = rects.front();
  long long sum = 0;
  for (const render_gl::PixelRect& r : rects) {
    box = {std::min(box.x0, r.x0), std::min(box.y0, r.y0), std::max(box.x1, r.x1),
           std::max(box.y1, r.y1)};
    sum += r.area();
  }
  constexpr std::size_t kMaxRects = 16;
  if (rects.size() > kMaxRects || box.area() <= sum) rects.assign(1, box);
  return rects;
}

}  // namespace impasto::app::window
