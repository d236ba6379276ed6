#pragma once
// What ImGui's drawing changed on screen since the last frame, so that a window keeping its
// last frame re-draws and re-presents only those pixels. Each draw list (one a panel) is
// flattened into its triangles with their clip rectangle and texture; the triangles between
// the longest common prefix and suffix of a list's last and new sequence are what changed
// (a new status figure, a moved slider), and their boxes, old and new, are the damage.
#include <imgui.h>
#include <impasto/render_gl/shaded_view_cache.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace impasto::app::window {

// A rectangle in ImGui's display coordinates (origin top-left), [x0, x1) × [y0, y1).
struct UiRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const UiRect&) const = default;
};

// One triangle as ImGui draws it: its vertices, the command's clip rectangle and texture.
struct UiTriangle {
  float x[3] = {}, y[3] = {}, u[3] = {}, v[3] = {};
  std::uint32_t colour[3] = {};
  UiRect clip;
  std::uintptr_t texture = 0;
  bool operator==(const UiTriangle&) const = default;
  // The pixels it can touch: its box within its clip rectangle, a pixel wider for the
  // anti-aliased fringe.
  UiRect box() const;
};

// The boxes of the triangles that differ between `before` and `after` (one list's frames),
// merged into one rectangle; empty when the lists draw the same.
UiRect changed_box(std::span<const UiTriangle> before, std::span<const UiTriangle> after);

// The triangles of one draw list, in drawing order.
std::vector<UiTriangle> flatten(const ImDrawList& list);

// `rect` (ImGui coordinates, `scale` framebuffer pixels a unit) as the framebuffer's pixels
// (origin bottom-left) that cover it, clipped to the framebuffer.
render_gl::PixelRect to_gl_pixels(const UiRect& rect, double scale, int fb_w, int fb_h);
// The framebuffer pixels `rect` in ImGui coordinates.
UiRect to_ui_rect(const render_gl::PixelRect& rect, double scale, int fb_h);

// Clips every command of `data` to `within` while alive (ImGui's backend then draws only
// those pixels), and gives the commands their own clip rectangles back when it ends.
class ClipDrawData {
 public:
  ClipDrawData(ImDrawData& data, const UiRect& within);
  ~ClipDrawData();
  ClipDrawData(const ClipDrawData&) = delete;
  ClipDrawData& operator=(const ClipDrawData&) = delete;

 private:
  ImDrawData& data_;
  std::vector<ImVec4> saved_;
};

class UiDamage {
 public:
  // The rectangles (one per changed draw list) whose pixels differ from the last frame's
  // drawing; remembers this frame's.
  std::vector<UiRect> update(const ImDrawData& data);
  // A texture whose texels changed this frame (a panel re-uploaded it): the triangles that
  // draw it are damaged in the next update(), though they are drawn the same.
  void texture_changed(std::uintptr_t texture) { changed_textures_.push_back(texture); }

 private:
  struct List {
    std::string owner;
    std::vector<UiTriangle> triangles;
  };
  std::vector<List> last_;
  std::vector<std::uintptr_t> changed_textures_;
};

}  // namespace impasto::app::window
