#include "window/palette_board_panel.hpp"

#include "window/eyedropper.hpp"

#include <imgui.h>
#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace impasto::app::window {
namespace {

constexpr float kBoardWidthPx = 300.0f;  // the panel's width, less its margins

}  // namespace

PaletteBoardPanel::PaletteBoardPanel()
    : feed_([this](input::StrokeEvent event) { board_.apply(event); }) {}

void PaletteBoardPanel::replace(PaletteBoard board) {
  board_ = std::move(board);
  renderer_.reset();
  full_render_ = true;
}

// The board through the CPU reference renderer, only its dirty tiles, into an RGBA8 texture.
// Returns whether the texture changed.
bool PaletteBoardPanel::refresh_image(const render::RenderSettings& settings) {
  const paintcore::Painting& painting = board_.painting();
  const paintcore::Canvas& canvas = painting.canvas();
  const std::vector<int> dirty = paintcore::tile_indices(board_.take_changes());
  const bool new_look = !renderer_ || painting.pigment_slots() != rendered_slots_ ||
                        settings.light != rendered_light_ ||
                        settings.wavelengths != rendered_wavelengths_;
  if (new_look) {
    render::RenderSettings board_settings = settings;
    board_settings.threads = 1;  // small: not worth the simulation thread's cores
    renderer_ = std::make_unique<render::TileRenderer>(board_settings, painting.pigment_slots());
    rendered_slots_ = painting.pigment_slots();
    rendered_light_ = settings.light;
    rendered_wavelengths_ = settings.wavelengths;
    full_render_ = true;
  }
  if (!full_render_ && dirty.empty()) return false;
  if (full_render_) {
    renderer_->render_all(canvas);
  } else {
    renderer_->update(canvas, dirty);
  }
  full_render_ = false;
  const render::Image image = renderer_->image();
  if (texture_.width() != image.width || texture_.height() != image.height) {
    texture_ = render_gl::Texture(image.width, image.height, 0, render_gl::TexelFormat::kRGBA8);
  }
  rgba_.resize(4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (std::size_t i = 0, n = rgba_.size() / 4; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = std::clamp(image.rgb[3 * i + static_cast<std::size_t>(c)], 0.0f, 1.0f);
      rgba_[4 * i + static_cast<std::size_t>(c)] = static_cast<unsigned char>(std::lround(v * 255));
    }
    rgba_[4 * i + 3] = 255;
  }
  texture_.upload(0, 0, image.width, image.height, 0, rgba_.data(), image.width);
  return true;
}

void PaletteBoardPanel::draw(WindowState& s, session::SimWorker& worker) {
  if (!ImGui::CollapsingHeader("Palette board", ImGuiTreeNodeFlags_DefaultOpen)) return;
  board_.set_brush(s.brush);
  // (ImGui draws the board the same whatever its texels: the window is told they changed.)
  if (refresh_image(s.settings))
    s.ui_textures_changed.push_back(static_cast<std::uintptr_t>(texture_.id()));
  const float scale = kBoardWidthPx / static_cast<float>(texture_.width());
  const ImVec2 size(kBoardWidthPx, scale * static_cast<float>(texture_.height()));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_.id())), size);
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton("##board", size);

  // The mouse on the board: mm of the board from the image's pixels.
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const double mm_per_px = board_.width_mm() / kBoardWidthPx;
  const double x_mm = (mouse.x - origin.x) * mm_per_px;
  const double y_mm = (mouse.y - origin.y) * mm_per_px;
  if (tool_ == Tool::kLayOut && ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    const auto& pigments = data::PigmentDatabase::defaults().all();
    std::vector<input::PigmentPart> mix;
    for (std::size_t i = 0; i < pigments.size() && i < s.mix_parts.size(); ++i) {
      if (s.mix_parts[i] > 0.0f) mix.push_back({pigments[i].name, s.mix_parts[i]});
    }
    if (mix.empty()) {
      message_ = "choose pigments in the Palette panel first";
    } else {
      try {
        board_.lay_out(mix, s.load_volume_mm3, x_mm, y_mm);
        message_.clear();
      } catch (const std::exception& e) {
        message_ = e.what();
      }
    }
  } else if (tool_ == Tool::kMix) {
    const bool down = ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left);
    if (down || feed_.in_stroke()) {
      paintcore::PenSample sample;
      sample.time_s = ImGui::GetTime();
      sample.x_mm = x_mm;
      sample.y_mm = y_mm;
      sample.pressure = down ? s.mouse_pressure : 0.0f;
      sample.buttons = paintcore::kPenInRange | (down ? paintcore::kPenTip : 0u);
      try {
        feed_.feed(sample);
      } catch (const std::exception& e) {
        message_ = e.what();
      }
    }
  }

  int tool = tool_ == Tool::kMix ? 1 : 0;
  ImGui::RadioButton("lay out paint", &tool, 0);
  ImGui::SameLine();
  ImGui::RadioButton("mix with brush", &tool, 1);
  tool_ = tool == 1 ? Tool::kMix : Tool::kLayOut;
  const auto load = board_.pick_up();
  ImGui::BeginDisabled(!load);
  if (ImGui::Button("Pick up onto brush") && load) {
    // The canvas brush gets exactly what the board brush holds, mixed with the Palette
    // panel's medium (as its Load is); the board brush is wiped.
    input::LoadEvent picked = *load;
    picked.medium = load_event(s).medium;
    load_onto_brush(worker, std::move(picked));
    board_.wipe_brush();
  }
  ImGui::EndDisabled();
  if (ImGui::Button("Wipe board brush")) board_.wipe_brush();
  ImGui::SameLine();
  if (ImGui::Button("Clean board")) replace(PaletteBoard());
  ImGui::Text("board brush holds %.1f mm³", load ? load->volume_mm3 : 0.0);
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
}

}  // namespace impasto::app::window
