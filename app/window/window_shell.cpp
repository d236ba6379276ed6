#include "window/window_shell.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the panels' rectangles, to tell where a press landed
#include <impasto/render_gl/gl.hpp>

#include <atomic>
#include <csignal>
#include <iostream>
#include <stdexcept>

#include "window/opening_note.hpp"
#include "window/pointer_server_times.hpp"
#include "window/screenshot.hpp"
#include "window/window_present.hpp"

namespace impasto::app::window {
namespace {

std::atomic<bool> g_signalled{false};

extern "C" void note_signal(int) {
  g_signalled.store(true);
}

WindowShell& shell_of(GLFWwindow* window) {
  return *static_cast<WindowShell*>(glfwGetWindowUserPointer(window));
}

}  // namespace

static_assert(kLeftButton == GLFW_MOUSE_BUTTON_LEFT && kRightButton == GLFW_MOUSE_BUTTON_RIGHT &&
              kMiddleButton == GLFW_MOUSE_BUTTON_MIDDLE);

WindowShell::Glfw::Glfw() {
  glfwSetErrorCallback([](int code, const char* text) {
    std::cerr << "impasto: GLFW error " << code << ": " << text << "\n";
  });
  if (!glfwInit()) {
    throw std::runtime_error(
        "cannot open a window: GLFW found no display (set DISPLAY, or run under xvfb-run)");
  }
}

WindowShell::Glfw::~Glfw() {
  glfwTerminate();
}

WindowShell::WindowShell(int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw std::runtime_error("cannot open a window with OpenGL 3.3 core");
  shown_title_ = title;
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  render_gl::load_gl(reinterpret_cast<GLADloadfunc>(&glfwGetProcAddress));
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // panels are laid out in code, nothing to remember
  ImGui::StyleColorsDark();
  // The mouse's events are queued with their times as they arrive. Installed before ImGui's
  // backend, which keeps these callbacks and calls them before its own.
  server_times_ = std::make_unique<PointerServerTimes>(window_);
  glfwSetWindowUserPointer(window_, this);
  glfwSetCursorPosCallback(window_, [](GLFWwindow* window, double x, double y) {
    WindowShell& self = shell_of(window);
    self.pointer_events_.moved(x, y, self.server_times_->move_time(x, y));
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* window, int button, int action, int) {
    WindowShell& self = shell_of(window);
    const bool pressed = action == GLFW_PRESS;
    self.pointer_events_.button(button, pressed, self.server_times_->button_time(button, pressed));
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* window, double, double) {
    WindowShell& self = shell_of(window);
    self.wheel_times_.push_back(self.server_times_->wheel_time());
  });
  // Key presses are queued as they arrive (a press and release within one frame still counts).
  glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int mods) {
    if (action != GLFW_RELEASE)
      shell_of(window).key_presses_.push_back({key, mods, action == GLFW_REPEAT});
  });
  // Exposed again after being covered: the window's pixels are drawn whole.
  glfwSetWindowRefreshCallback(window_,
                               [](GLFWwindow* window) { shell_of(window).present_whole_ = true; });
  double cursor_x = 0, cursor_y = 0;
  glfwGetCursorPos(window_, &cursor_x, &cursor_y);
  pointer_events_.set_position(cursor_x, cursor_y);
  presenter_ = std::make_unique<WindowPresenter>(window_);
  crosshair_ = glfwCreateStandardCursor(GLFW_CROSSHAIR_CURSOR);
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

WindowShell::~WindowShell() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (crosshair_) glfwDestroyCursor(crosshair_);
  glfwDestroyWindow(window_);
}

double WindowShell::now_s() const {
  return glfwGetTime();
}

void WindowShell::close_on_signals() {
  for (int signal : {SIGTERM, SIGINT, SIGHUP}) std::signal(signal, note_signal);
}

bool WindowShell::signalled() {
  return g_signalled.load();
}

void WindowShell::poll() {
  server_times_->scan();  // the waiting events' own times, before GLFW delivers them
  glfwPollEvents();
  if (glfwWindowShouldClose(window_)) {
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
    close_requested_ = true;
  }
}

bool WindowShell::take_close_request() {
  return std::exchange(close_requested_, false);
}

std::size_t WindowShell::server_timed() const {
  return server_times_->matched();
}

std::size_t WindowShell::delivery_timed() const {
  return server_times_->unmatched();
}

void WindowShell::window_size(int& w, int& h) const {
  glfwGetWindowSize(window_, &w, &h);
}

void WindowShell::framebuffer_size(int& w, int& h) const {
  glfwGetFramebufferSize(window_, &w, &h);
}

void WindowShell::cursor(double& x, double& y) const {
  glfwGetCursorPos(window_, &x, &y);
}

std::array<double, 2> WindowShell::window_origin_px() const {
  int x = 0, y = 0;
  glfwGetWindowPos(window_, &x, &y);
  return {static_cast<double>(x), static_cast<double>(y)};
}

std::array<double, 4> WindowShell::screen_px() const {
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0;
    glfwGetMonitorPos(monitor, &x, &y);
    if (const GLFWvidmode* mode = glfwGetVideoMode(monitor))
      return {static_cast<double>(x), static_cast<double>(y), static_cast<double>(mode->width),
              static_cast<double>(mode->height)};
  }
  int w = 0, h = 0;
  window_size(w, h);
  const std::array<double, 2> origin = window_origin_px();
  return {origin[0], origin[1], static_cast<double>(w), static_cast<double>(h)};
}

bool WindowShell::key_down(int key) const {
  return glfwGetKey(window_, key) == GLFW_PRESS;
}

void WindowShell::set_title(const std::string& title) {
  if (title == shown_title_) return;
  glfwSetWindowTitle(window_, title.c_str());
  shown_title_ = title;
}

void WindowShell::set_crosshair(bool on) {
  if (on == crosshair_on_) return;
  crosshair_on_ = on;
  ImGuiIO& io = ImGui::GetIO();
  if (on) {
    io.ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange;
    glfwSetCursor(window_, crosshair_);
  } else {
    io.ConfigFlags &= ~ImGuiConfigFlags_NoMouseCursorChange;
    glfwSetCursor(window_, nullptr);
  }
}

void WindowShell::begin_ui_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

// Where the back buffer keeps the last frame (WindowPresenter::partial), each changed
// rectangle is drawn as the canvas with every panel over it, so a pixel drawn is drawn whole.
void WindowShell::present(std::span<const render_gl::PixelRect> canvas_changed,
                          std::span<const std::uintptr_t> ui_textures_changed, double fb_scale,
                          const std::filesystem::path* screenshot,
                          const std::function<void(const render_gl::PixelRect&)>& draw_canvas) {
  int fb_w = 0, fb_h = 0;
  framebuffer_size(fb_w, fb_h);
  ImDrawData& ui = *ImGui::GetDrawData();
  for (const std::uintptr_t texture : ui_textures_changed) ui_damage_.texture_changed(texture);
  const std::vector<UiRect> ui_changed = ui_damage_.update(ui);
  const bool whole = !presenter_->partial() || present_whole_ || screenshot ||
                     fb_w != presented_w_ || fb_h != presented_h_;
  present_whole_ = false;
  presented_w_ = fb_w;
  presented_h_ = fb_h;
  glViewport(0, 0, fb_w, fb_h);
  if (whole) {
    draw_canvas({0, 0, fb_w, fb_h});
    ImGui_ImplOpenGL3_RenderDrawData(&ui);
    if (screenshot) save_window_screenshot(*screenshot, fb_w, fb_h);
    presenter_->present_all();
    return;
  }
  std::vector<render_gl::PixelRect> rects(canvas_changed.begin(), canvas_changed.end());
  for (const UiRect& r : ui_changed) rects.push_back(to_gl_pixels(r, fb_scale, fb_w, fb_h));
  rects = merge_rects(std::move(rects));
  for (const render_gl::PixelRect& r : rects) {
    draw_canvas(r);
    const ClipDrawData clipped(ui, to_ui_rect(r, fb_scale, fb_h));
    ImGui_ImplOpenGL3_RenderDrawData(&ui);
  }
  presenter_->present_parts(rects);
}

void WindowShell::present_over_background(const std::array<float, 3>& background_rgb) {
  int fb_w = 0, fb_h = 0;
  framebuffer_size(fb_w, fb_h);
  clear_to_background(background_rgb, fb_w, fb_h);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  presenter_->present_all();
  present_whole_ = true;
}

// The rule behind io.WantCaptureMouse, asked for where the press happened rather than where
// the cursor is at the frame.
bool ui_at(double x, double y) {
  const ImGuiContext& g = *GImGui;
  if (g.OpenPopupStack.Size > 0) return true;
  const ImVec2 p(static_cast<float>(x), static_cast<float>(y));
  for (const ImGuiWindow* window : g.Windows) {
    if (window->Active && !window->Hidden && !(window->Flags & ImGuiWindowFlags_NoMouseInputs) &&
        window->OuterRectClipped.Contains(p)) {
      return true;
    }
  }
  return false;
}

bool ui_has_keyboard() {
  return ImGui::GetIO().WantTextInput || GImGui->OpenPopupStack.Size > 0;
}

}  // namespace impasto::app::window
