#include "window/reference_image.hpp"

#include <imgui.h>
#include <impasto/render_gl/gl.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "impasto/files/message_text.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/image.hpp"
#include "window/colour_target.hpp"

namespace impasto::app::window {
namespace {

// How far a press may move and still count as a click (a pick), not a drag (a pan); pixels.
constexpr float kClickSlop = 3.0f;

}  // namespace

std::array<float, 3> picked_colour(const ReferencePixels& pixels, int x, int y) {
  std::array<double, 3> sum{};
  int count = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= pixels.width || py >= pixels.height) continue;
      const std::size_t at = 3 * (static_cast<std::size_t>(py) * pixels.width + px);
      for (std::size_t c = 0; c < 3; ++c)
        sum[c] += render::srgb_decoded(pixels.rgb[at + c] / 255.0);
      ++count;
    }
  std::array<float, 3> rgb{};
  for (std::size_t c = 0; c < 3; ++c)
    rgb[c] = count > 0 ? static_cast<float>(render::srgb_encoded(sum[c] / count)) : 0.0f;
  return rgb;
}

ReferenceImage::~ReferenceImage() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void ReferenceImage::open(const std::filesystem::path& file, WindowState& s) {
  render::Image image;
  try {
    image = render::read_picture(file);  // PNG or JPEG, sizes checked against the budget
  } catch (const std::exception& e) {
    s.notifications.error(std::string("reference image: ") + e.what());
    return;
  }
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  if (image.width > largest || image.height > largest) {
    s.notifications.error("reference image: " + files::terminal_text(file.string()) + " is " +
                          std::to_string(image.width) + " x " + std::to_string(image.height) +
                          " pixels, more than the GPU's " + std::to_string(largest));
    return;
  }
  pixels_.width = image.width;
  pixels_.height = image.height;
  pixels_.rgb.resize(image.rgb.size());
  std::transform(image.rgb.begin(), image.rgb.end(), pixels_.rgb.begin(), [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  });
  if (!texture_) glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // pixels, close up
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, pixels_.width, pixels_.height, 0, GL_RGB,
               GL_UNSIGNED_BYTE, pixels_.rgb.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  title_ = "Reference: " + files::terminal_text(file.filename().string()) + "###reference";
  open_ = true;
  fit_ = true;
}

void ReferenceImage::draw(WindowState& s, ColourTarget& target) {
  if (s.reference_requested) {
    const std::filesystem::path file = *s.reference_requested;
    s.reference_requested.reset();
    open(file, s);
  }
  if (!open_) return;
  ImGui::SetNextWindowSize(ImVec2(420, 340), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImVec2(40, 140), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin(title_.c_str(), &open_, ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 16.0f),
                    std::max(ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeight(), 16.0f));
  if (fit_) {
    image_per_screen_ = std::max(pixels_.width / static_cast<double>(size.x),
                                 pixels_.height / static_cast<double>(size.y));
    centre_ = {0.5 * pixels_.width, 0.5 * pixels_.height};
    fit_ = false;
  }
  ImGui::InvisibleButton("##view", size);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  // The image point under a screen point.
  const auto image_at = [&](ImVec2 p) {
    return std::array<double, 2>{centre_[0] + (p.x - origin.x - 0.5 * size.x) * image_per_screen_,
                                 centre_[1] + (p.y - origin.y - 0.5 * size.y) * image_per_screen_};
  };
  if (hovered && io.MouseWheel != 0.0f) {  // zoom about the pointer
    const std::array<double, 2> before = image_at(io.MousePos);
    image_per_screen_ = std::clamp(image_per_screen_ * std::pow(0.8, io.MouseWheel), 1.0 / 32,
                                   std::max(pixels_.width, pixels_.height) / 16.0);
    const std::array<double, 2> after = image_at(io.MousePos);
    centre_[0] += before[0] - after[0];
    centre_[1] += before[1] - after[1];
  }
  if (ImGui::IsItemActivated()) dragged_ = false;
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, kClickSlop)) {
    centre_[0] -= io.MouseDelta.x * image_per_screen_;
    centre_[1] -= io.MouseDelta.y * image_per_screen_;
    dragged_ = true;
  }
  const bool clicked = ImGui::IsItemDeactivated() && !dragged_;
  // The visible part of the image, as texture coordinates (outside it, clamped: the window's
  // background shows).
  const std::array<double, 2> top_left = image_at(origin);
  const std::array<double, 2> bottom_right = image_at(ImVec2(origin.x + size.x, origin.y + size.y));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto screen_of = [&](double ix, double iy) {
    return ImVec2(
        static_cast<float>(origin.x + 0.5 * size.x + (ix - centre_[0]) / image_per_screen_),
        static_cast<float>(origin.y + 0.5 * size.y + (iy - centre_[1]) / image_per_screen_));
  };
  const double x0 = std::max(0.0, top_left[0]), y0 = std::max(0.0, top_left[1]);
  const double x1 = std::min<double>(pixels_.width, bottom_right[0]);
  const double y1 = std::min<double>(pixels_.height, bottom_right[1]);
  if (x1 > x0 && y1 > y0) {
    draw->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture_)), screen_of(x0, y0),
        screen_of(x1, y1),
        ImVec2(static_cast<float>(x0 / pixels_.width), static_cast<float>(y0 / pixels_.height)),
        ImVec2(static_cast<float>(x1 / pixels_.width), static_cast<float>(y1 / pixels_.height)));
  }
  const std::array<double, 2> under = image_at(io.MousePos);
  const int px = static_cast<int>(std::floor(under[0])),
            py = static_cast<int>(std::floor(under[1]));
  const bool inside = px >= 0 && py >= 0 && px < pixels_.width && py < pixels_.height;
  if (clicked && inside) {
    target.pick(picked_colour(pixels_, px, py), s.settings.light);
  }
  if (hovered && inside) {
    const std::array<float, 3> here = picked_colour(pixels_, px, py);
    ImGui::Text("%d, %d  #%02X%02X%02X  click: the colour target", px, py,
                static_cast<int>(std::lround(here[0] * 255)),
                static_cast<int>(std::lround(here[1] * 255)),
                static_cast<int>(std::lround(here[2] * 255)));
  } else {
    ImGui::TextDisabled("%d x %d; drag: pan, wheel: zoom, click: pick", pixels_.width,
                        pixels_.height);
  }
  ImGui::End();
}

}  // namespace impasto::app::window
