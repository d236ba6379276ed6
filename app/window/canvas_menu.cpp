#include "window/canvas_menu.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <impasto/render/surface_brdf.hpp>
#include "window/enum_combo.hpp"
#include "window/imgui_layout.hpp"

namespace impasto::app::window {
namespace {

constexpr std::array<const char*, 9> kAnchorLabels = {"##tl", "##t",  "##tr", "##l", "##c",
                                                      "##r",  "##bl", "##b",  "##br"};
constexpr std::array<int, 3> kScales = {1, 2, 4};

}  // namespace

VarnishRequest varnish_request(paintcore::Finish finish, float thickness_mm, bool whole,
                               const std::array<int, 4>& region) {
  VarnishRequest request;
  request.finish = finish;
  // To the dialog's 3 decimals: the recording's `varnish` record reads "0.03", not the
  // float's widening.
  request.thickness_mm = std::round(1000.0 * thickness_mm) / 1000.0;
  if (!whole)
    request.region =
        paintcore::CellRect{region[0], region[1], region[0] + region[2], region[1] + region[3]};
  return request;
}

CanvasMenuRequest CanvasMenu::draw(int canvas_width, int canvas_height,
                                   const std::optional<std::filesystem::path>& painting_file) {
  if (ImGui::BeginMainMenuBar()) {  // appends to the window's menu bar
    if (ImGui::BeginMenu("Image")) {
      const auto open = [&](Dialog dialog) {
        open_ = dialog;
        canvas_w_ = canvas_width;
        canvas_h_ = canvas_height;
        width_ = canvas_width;
        height_ = canvas_height;
        crop_ = {0, 0, canvas_width, canvas_height};
        if (varnish_region_[2] <= 0) varnish_region_ = crop_;  // kept from the last coat
        const std::string stem =
            painting_file ? (painting_file->parent_path() / painting_file->stem()).string()
                          : std::string("painting");
        std::snprintf(stem_.data(), stem_.size(), "%s", stem.c_str());
      };
      if (ImGui::MenuItem("Resize canvas...")) open(Dialog::kResize);
      if (ImGui::MenuItem("Crop...")) open(Dialog::kCrop);
      if (ImGui::MenuItem("Varnish...")) open(Dialog::kVarnish);
      ImGui::Separator();
      if (ImGui::MenuItem("Export at scale and maps...")) open(Dialog::kExport);
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }
  switch (open_) {
    case Dialog::kResize:
      return draw_resize();
    case Dialog::kCrop:
      return draw_crop();
    case Dialog::kVarnish:
      return draw_varnish();
    case Dialog::kExport:
      return draw_export();
    case Dialog::kNone:
      break;
  }
  return {};
}

bool CanvasMenu::dialog(const char* title, const char* action, const std::function<bool()>& body) {
  bool open = true;
  const bool chosen = action_dialog(title, action, open, body);
  if (!open) open_ = Dialog::kNone;
  return chosen;
}

CanvasMenuRequest CanvasMenu::draw_resize() {
  CanvasMenuRequest request;
  const bool resize = dialog("Resize canvas", "Resize", [&] {
    ImGui::Text("Now %d x %d cells", canvas_w_, canvas_h_);
    ImGui::InputInt("width (cells)", &width_);
    ImGui::InputInt("height (cells)", &height_);
    width_ = std::clamp(width_, 1, paintcore::kMaxCanvasCells);
    height_ = std::clamp(height_, 1, paintcore::kMaxCanvasCells);
    ImGui::TextUnformatted("The painting sits at:");
    for (int k = 0; k < 9; ++k) {  // a 3 x 3 grid of anchors
      if (k % 3 != 0) ImGui::SameLine();
      ImGui::RadioButton(kAnchorLabels[static_cast<std::size_t>(k)], &anchor_, k);
    }
    if (width_ < canvas_w_ || height_ < canvas_h_)
      ImGui::TextWrapped("Smaller: the paint outside is cut away (Edit > Undo brings it back).");
    return true;
  });
  if (resize)
    request.frame = paintcore::anchored_frame(canvas_w_, canvas_h_, width_, height_,
                                              static_cast<paintcore::CanvasAnchor>(anchor_));
  return request;
}

CanvasMenuRequest CanvasMenu::draw_crop() {
  CanvasMenuRequest request;
  const bool crop = dialog("Crop", "Crop", [&] {
    ImGui::Text("Keep a rectangle of the %d x %d cells", canvas_w_, canvas_h_);
    ImGui::InputInt("left (cells)", &crop_[0]);
    ImGui::InputInt("top (cells)", &crop_[1]);
    crop_[0] = std::clamp(crop_[0], 0, canvas_w_ - 1);
    crop_[1] = std::clamp(crop_[1], 0, canvas_h_ - 1);
    ImGui::InputInt("width (cells)", &crop_[2]);
    ImGui::InputInt("height (cells)", &crop_[3]);
    crop_[2] = std::clamp(crop_[2], 1, canvas_w_ - crop_[0]);
    crop_[3] = std::clamp(crop_[3], 1, canvas_h_ - crop_[1]);
    ImGui::TextWrapped("The paint outside is cut away (Edit > Undo brings it back).");
    return true;
  });
  if (crop) request.frame = paintcore::crop_frame(crop_[0], crop_[1], crop_[2], crop_[3]);
  return request;
}

CanvasMenuRequest CanvasMenu::draw_varnish() {
  CanvasMenuRequest request;
  const bool apply = dialog("Varnish", "Varnish", [&] {
    enum_combo("finish", varnish_finish_, render::surface::kFinishNames);
    ImGui::SliderFloat("thickness (mm)", &varnish_mm_, 0.005f,
                       static_cast<float>(paintcore::kMaxVarnishMm), "%.3f",
                       ImGuiSliderFlags_Logarithmic);
    varnish_mm_ = std::clamp(varnish_mm_, 0.005f, static_cast<float>(paintcore::kMaxVarnishMm));
    ImGui::Checkbox("the whole painting", &varnish_whole_);
    // Shown either way, so that the dialog keeps the height it opened with.
    ImGui::BeginDisabled(varnish_whole_);
    ImGui::InputInt4("x, y, w, h (cells)", varnish_region_.data());
    ImGui::EndDisabled();
    varnish_region_[0] = std::clamp(varnish_region_[0], 0, canvas_w_ - 1);
    varnish_region_[1] = std::clamp(varnish_region_[1], 0, canvas_h_ - 1);
    varnish_region_[2] = std::clamp(varnish_region_[2], 1, canvas_w_ - varnish_region_[0]);
    varnish_region_[3] = std::clamp(varnish_region_[3], 1, canvas_h_ - varnish_region_[1]);
    ImGui::TextWrapped(
        "A coat over the paint: it goes on wet (glossy) and dries as paint does (Dry now); its "
        "finish replaces an older coat's. Edit > Undo takes it off.");
    return true;
  });
  if (apply)
    request.varnish =
        varnish_request(varnish_finish_, varnish_mm_, varnish_whole_, varnish_region_);
  return request;
}

session::ExportRequest export_request(const ExportChoice& choice) {
  session::ExportRequest e;
  e.scale = choice.scale;
  const std::string base =
      choice.stem + (choice.scale > 1 ? "@" + std::to_string(choice.scale) + "x" : "");
  if (choice.image) e.image = base + ".png";
  if (choice.height_format != 0)
    e.height_map = base + (choice.height_format == 1 ? ".height.png" : ".height.exr");
  if (choice.normal) e.normal_map = base + ".normal.png";
  switch (choice.solid) {
    case SolidFormat::kNone:
      break;
    case SolidFormat::kStl:
      e.solids.push_back(base + ".stl");
      break;
    case SolidFormat::kPly:
      e.solids.push_back(base + ".ply");
      break;
    case SolidFormat::kObj:
      e.solids.push_back(base + ".obj");
      break;
  }
  e.solid = choice.solid_options;
  return e;
}

CanvasMenuRequest CanvasMenu::draw_export() {
  CanvasMenuRequest request;
  ExportChoice& c = export_;
  const bool export_now = dialog("Export at scale and maps", "Export", [&] {
    ImGui::Combo("scale", &scale_index_,
                 "1x\0"
                 "2x\0"
                 "4x\0");
    c.scale = kScales[static_cast<std::size_t>(std::clamp(scale_index_, 0, 2))];
    ImGui::Text("%d x %d pixels, relief interpolated smoothly", canvas_w_ * c.scale,
                canvas_h_ * c.scale);
    ImGui::InputText("files (stem)", stem_.data(), stem_.size());
    c.stem = stem_.data();
    const std::string base = c.stem + (c.scale > 1 ? "@" + std::to_string(c.scale) + "x" : "");
    ImGui::Checkbox(("image: " + base + ".png").c_str(), &c.image);
    ImGui::TextUnformatted("height map (mm):");
    ImGui::SameLine();
    ImGui::RadioButton("none", &c.height_format, 0);
    ImGui::SameLine();
    ImGui::RadioButton("16-bit PNG", &c.height_format, 1);
    ImGui::SameLine();
    ImGui::RadioButton("float EXR", &c.height_format, 2);
    ImGui::Checkbox(("normal map, OpenGL +Y up: " + base + ".normal.png").c_str(), &c.normal);
    // The relief as a closed mesh in mm at the painting's size, for a 3D printer or a viewer
    // (docs/canvas-and-export.md).
    int solid = static_cast<int>(c.solid);
    ImGui::TextUnformatted("solid (mm):");
    ImGui::SameLine();
    ImGui::RadioButton("none##solid", &solid, 0);
    ImGui::SameLine();
    ImGui::RadioButton("STL", &solid, 1);
    ImGui::SameLine();
    ImGui::RadioButton("PLY, coloured", &solid, 2);
    ImGui::SameLine();
    ImGui::RadioButton("OBJ, coloured", &solid, 3);
    c.solid = static_cast<SolidFormat>(solid);
    if (c.solid != SolidFormat::kNone) {
      float base_mm = static_cast<float>(c.solid_options.base_mm);
      if (ImGui::InputFloat("base (mm)", &base_mm, 0.5f, 1.0f, "%.2f"))
        c.solid_options.base_mm = std::clamp(static_cast<double>(base_mm), 0.01, 100.0);
      float relief = static_cast<float>(c.solid_options.relief_scale);
      if (ImGui::InputFloat("relief x", &relief, 0.5f, 1.0f, "%.2f"))
        c.solid_options.relief_scale = std::clamp(static_cast<double>(relief), 0.1, 100.0);
      float error = static_cast<float>(c.solid_options.max_error_mm);
      if (ImGui::InputFloat("max error (mm)", &error, 0.01f, 0.05f, "%.3f"))
        c.solid_options.max_error_mm = std::clamp(static_cast<double>(error), 0.0, 10.0);
    }
    const bool any = c.image || c.height_format != 0 || c.normal || c.solid != SolidFormat::kNone;
    return any && !c.stem.empty();
  });
  if (export_now) request.exports = export_request(c);
  return request;
}

}  // namespace impasto::app::window
