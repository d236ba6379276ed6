#include "window/ui_damage.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace impasto::app::window {
namespace {

UiRect merge(const UiRect& a, const UiRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

UiRect box_of(std::span<const UiTriangle> triangles) {
  UiRect box;
  for (const UiTriangle& t : triangles) box = merge(box, t.box());
  return box;
}

}  // namespace

UiRect UiTriangle::box() const {
  const auto [lo_x, hi_x] = std::minmax({x[0], x[1], x[2]});
  const auto [lo_y, hi_y] = std::minmax({y[0], y[1], y[2]});
  const UiRect r{std::max(lo_x - 1.0f, clip.x0), std::max(lo_y - 1.0f, clip.y0),
                 std::min(hi_x + 1.0f, clip.x1), std::min(hi_y + 1.0f, clip.y1)};
  return r.empty() ? UiRect{} : r;
}

UiRect changed_box(std::span<const UiTriangle> before, std::span<const UiTriangle> after) {
  const std::size_t shorter = std::min(before.size(), after.size());
  std::size_t prefix = 0;
  while (prefix < shorter && before[prefix] == after[prefix]) ++prefix;
  std::size_t suffix = 0;
  while (suffix < shorter - prefix &&
         before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix]) {
    ++suffix;
  }
  return merge(box_of(before.subspan(prefix, before.size() - prefix - suffix)),
               box_of(after.subspan(prefix, after.size() - prefix - suffix)));
}

std::vector<UiTriangle> flatten(const ImDrawList& list) {
  std::vector<UiTriangle> triangles;
  triangles.reserve(static_cast<std::size_t>(list.IdxBuffer.Size / 3));
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    if (cmd.UserCallback != nullptr) continue;  // state changes, not pixels
    const UiRect clip{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w};
    for (unsigned i = 0; i + 2 < cmd.ElemCount; i += 3) {
      UiTriangle t;
      for (int k = 0; k < 3; ++k) {
        const ImDrawVert& vertex = list.VtxBuffer[static_cast<int>(
            cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + i + k)])];
        t.x[k] = vertex.pos.x;
        t.y[k] = vertex.pos.y;
        t.u[k] = vertex.uv.x;
        t.v[k] = vertex.uv.y;
        t.colour[k] = vertex.col;
      }
      t.clip = clip;
      t.texture = reinterpret_cast<std::uintptr_t>(cmd.TextureId);
      triangles.push_back(t);
    }
  }
  return triangles;
}

render_gl::PixelRect to_gl_pixels(const UiRect& rect, double scale, int fb_w, int fb_h) {
  const auto clamp_to = [](double v, int limit) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(limit)));
  };
  return {clamp_to(std::floor(rect.x0 * scale), fb_w),
          clamp_to(fb_h - std::ceil(rect.y1 * scale), fb_h),
          clamp_to(std::ceil(rect.x1 * scale), fb_w),
          clamp_to(fb_h - std::floor(rect.y0 * scale), fb_h)};
}

UiRect to_ui_rect(const render_gl::PixelRect& rect, double scale, int fb_h) {
  return {static_cast<float>(rect.x0 / scale), static_cast<float>((fb_h - rect.y1) / scale),
          static_cast<float>(rect.x1 / scale), static_cast<float>((fb_h - rect.y0) / scale)};
}

ClipDrawData::ClipDrawData(ImDrawData& data, const UiRect& within) : data_(data) {
  for (int i = 0; i < data_.CmdListsCount; ++i) {
    for (ImDrawCmd& cmd : data_.CmdLists[i]->CmdBuffer) {
      saved_.push_back(cmd.ClipRect);
      const ImVec2 offset = data_.DisplayPos;  // clip rectangles include the display's origin
      cmd.ClipRect = {std::max(cmd.ClipRect.x, within.x0 + offset.x),
                      std::max(cmd.ClipRect.y, within.y0 + offset.y),
                      std::min(cmd.ClipRect.z, within.x1 + offset.x),
                      std::min(cmd.ClipRect.w, within.y1 + offset.y)};
    }
  }
}

ClipDrawData::~ClipDrawData() {
  std::size_t next = 0;
  for (int i = 0; i < data_.CmdListsCount; ++i) {
    for (ImDrawCmd& cmd : data_.CmdLists[i]->CmdBuffer) cmd.ClipRect = saved_[next++];
  }
}

std::vector<UiRect> UiDamage::update(const ImDrawData& data) {
  std::vector<List> lists;
  lists.reserve(static_cast<std::size_t>(data.CmdListsCount));
  for (int i = 0; i < data.CmdListsCount; ++i) {
    const ImDrawList& list = *data.CmdLists[i];
    lists.push_back({list._OwnerName ? list._OwnerName : "", flatten(list)});
  }
  std::vector<UiRect> damage;
  // Windows drawn in another order (a click brought one to the front): their overlaps may
  // show another window now, so everything any of them covers is damaged.
  const bool same_order =
      lists.size() == last_.size() &&
      std::equal(lists.begin(), lists.end(), last_.begin(),
                 [](const List& a, const List& b) { return a.owner == b.owner; });
  if (!same_order) {
    UiRect all;
    for (const List& list : lists) all = merge(all, box_of(list.triangles));
    for (const List& list : last_) all = merge(all, box_of(list.triangles));
    last_ = std::move(lists);
    changed_textures_.clear();  // (all is damaged anyway)
    if (!all.empty()) damage.push_back(all);
    return damage;
  }
  // A list is compared with the last frame's list of the same window; a window that came or
  // went damages all it covered.
  std::vector<bool> matched(last_.size(), false);
  for (const List& list : lists) {
    const auto old = std::find_if(last_.begin(), last_.end(), [&](const List& l) {
      return !matched[static_cast<std::size_t>(&l - last_.data())] && l.owner == list.owner;
    });
    UiRect box;
    if (old == last_.end()) {
      box = box_of(list.triangles);
    } else {
      matched[static_cast<std::size_t>(old - last_.begin())] = true;
      box = changed_box(old->triangles, list.triangles);
    }
    // Triangles drawing a texture whose texels changed.
    for (const UiTriangle& t : list.triangles)
      if (std::find(changed_textures_.begin(), changed_textures_.end(), t.texture) !=
          changed_textures_.end())
        box = merge(box, t.box());
    if (!box.empty()) damage.push_back(box);
  }
  changed_textures_.clear();
  for (std::size_t i = 0; i < last_.size(); ++i) {
    const UiRect box = matched[i] ? UiRect{} : box_of(last_[i].triangles);
    if (!box.empty()) damage.push_back(box);
  }
  last_ = std::move(lists);
  return damage;
}

}  // namespace impasto::app::window
