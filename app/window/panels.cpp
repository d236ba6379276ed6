#include "window/panels.hpp"
#include "impasto/files/message_text.hpp"
#include "window/colour_target.hpp"
#include "window/edit_help_menus.hpp"
#include "window/enum_combo.hpp"
#include "window/imgui_layout.hpp"
#include "window/light_disc_look.hpp"
#include "window/paint_strip.hpp"
#include "window/palette_medium.hpp"
#include "window/plot.hpp"
#include "window/shortcuts.hpp"
#include "window/surface_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

namespace impasto::app::window {
namespace {

constexpr float kPanelWidth = 330.0f;

// A menu item's shortcut text, from the one table (shortcuts.hpp); valid until the next call
// (ImGui reads it during the item's call only).
const char* keys(Command command) {
  static std::string text;
  text = shortcut_text(command);
  return text.c_str();
}

FileBrowserRequest browser_request(FilePurpose purpose, const WindowState& s) {
  FileBrowserRequest request;
  request.purpose = purpose;
  request.painting = s.file;
  request.recent_files = s.recent;
  switch (purpose) {
    case FilePurpose::kOpenPainting:
      request.title = "Open painting";
      request.accept_label = "Open";
      break;
    case FilePurpose::kSavePainting:
      request.title = "Save painting as";
      request.accept_label = "Save";
      break;
    case FilePurpose::kExportImage:
      request.title = "Export image";
      request.accept_label = "Export";
      break;
    case FilePurpose::kOpenStrokes:
      request.title = "Open strokes";
      request.accept_label = "Open";
      break;
    case FilePurpose::kOpenReference:
      request.title = "Open a reference image";
      request.accept_label = "Open";
      break;
  }
  return request;
}

// What the unsaved-changes prompt is about to do, for its question.
std::string pending_words(const WindowState& s) {
  switch (s.pending) {
    case PendingAction::kQuit:
      return "quitting";
    case PendingAction::kNew:
      return "starting a new painting";
    case PendingAction::kOpen:
    case PendingAction::kOpenRecent:
      return "opening " + s.pending_path.filename().string();
    case PendingAction::kNone:
      break;
  }
  return "going on";
}

// Save, Discard or Cancel before an action that would drop unsaved paint. Save on an
// untitled painting goes through Save as, and the action follows once it is saved.
void unsaved_prompt(PanelContext& c) {
  WindowState& s = c.state;
  if (s.ask_unsaved) {
    ImGui::OpenPopup("Unsaved changes");
    s.ask_unsaved = false;
  }
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    return;
  }
  const std::string name = s.file ? s.file->filename().string() : std::string("Untitled");
  ImGui::Text("Save the changes to %s before %s?", name.c_str(), pending_words(s).c_str());
  ImGui::TextDisabled("Changes you discard are lost.");
  ImGui::Spacing();
  const ImVec2 button(100.0f, 0.0f);
  if (ImGui::Button(s.file ? "Save" : "Save as...", button)) {
    ImGui::CloseCurrentPopup();
    if (!s.file) {
      s.continue_after_save = true;
      s.file_browser.open(browser_request(FilePurpose::kSavePainting, s));
    } else if (c.files.save(*s.file)) {
      s.pending_confirmed = true;
    } else {
      s.pending = PendingAction::kNone;  // not saved: nothing is discarded
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", button)) {
    s.pending_confirmed = true;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", button) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    s.pending = PendingAction::kNone;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Save found the painting's file changed on disk since this window read or wrote it (another
// window, or another program, saved it): Overwrite it, Save as another file, Reload it (this
// window's unsaved paint is dropped) or Cancel.
void changed_on_disk_prompt(PanelContext& c) {
  WindowState& s = c.state;
  if (s.ask_changed_on_disk) {
    ImGui::OpenPopup("Changed on disk");
    s.ask_changed_on_disk = false;
  }
  if (!ImGui::BeginPopupModal("Changed on disk", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    return;
  }
  const std::string name =
      s.file ? files::terminal_text(s.file->filename().string()) : std::string("The painting");
  ImGui::Text("%s changed on disk since this window opened or saved it.", name.c_str());
  ImGui::TextDisabled("Another window or program saved it. Overwrite replaces that work.");
  ImGui::Spacing();
  const ImVec2 button(100.0f, 0.0f);
  if (ImGui::Button("Overwrite", button)) {
    ImGui::CloseCurrentPopup();
    if (s.file) c.files.save_over(*s.file);
  }
  ImGui::SameLine();
  if (ImGui::Button("Save as...", button)) {
    ImGui::CloseCurrentPopup();
    s.file_browser.open(browser_request(FilePurpose::kSavePainting, s));
  }
  ImGui::SameLine();
  if (ImGui::Button("Reload", button)) {
    ImGui::CloseCurrentPopup();
    if (s.file) {
      s.pending = PendingAction::kOpen;  // the user chose to drop this window's paint
      s.pending_path = *s.file;
      s.pending_confirmed = true;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", button) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// The New painting dialog's size: a standard size (turned for landscape) or a custom one in
// cells, mm, cm or inches, at a resolution; the cells it makes, shown and kept in
// new_width / new_height.
void new_painting_size(WindowState& s) {
  const auto standard = [&](int i) { return kStandardSizes[static_cast<std::size_t>(i)]; };
  const auto set_standard = [&] {
    if (s.new_standard < 0) return;
    const StandardSize size = standard(s.new_standard);
    s.new_width_mm = s.new_landscape ? size.height_mm : size.width_mm;
    s.new_height_mm = s.new_landscape ? size.width_mm : size.height_mm;
  };
  const std::string current =
      s.new_standard < 0 ? std::string("custom") : std::string(standard(s.new_standard).name);
  ImGui::SetNextItemWidth(160.0f);
  if (ImGui::BeginCombo("size", current.c_str())) {
    if (ImGui::Selectable("custom", s.new_standard < 0)) s.new_standard = -1;
    for (int i = 0; i < static_cast<int>(kStandardSizes.size()); ++i) {
      if (ImGui::Selectable(std::string(standard(i).name).c_str(), s.new_standard == i)) {
        s.new_standard = i;
        set_standard();
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Checkbox("landscape", &s.new_landscape)) {
    if (s.new_standard >= 0) {
      set_standard();
    } else if ((s.new_width_mm < s.new_height_mm) == s.new_landscape) {
      std::swap(s.new_width_mm, s.new_height_mm);
    }
  }
  ImGui::SetNextItemWidth(160.0f);
  int unit = static_cast<int>(s.new_unit);
  const std::string unit_name(kSizeUnitNames[static_cast<std::size_t>(unit)]);
  if (ImGui::BeginCombo("unit", unit_name.c_str())) {
    for (int i = 0; i < static_cast<int>(kSizeUnitNames.size()); ++i) {
      const std::string name(kSizeUnitNames[static_cast<std::size_t>(i)]);
      if (ImGui::Selectable(name.c_str(), unit == i)) s.new_unit = static_cast<SizeUnit>(i);
    }
    ImGui::EndCombo();
  }
  const double dpi = std::max(1.0, static_cast<double>(s.new_dpi));
  const char* format = s.new_unit == SizeUnit::cells ? "%.0f" : "%.2f";
  for (auto [label, mm] :
       {std::pair{"width", &s.new_width_mm}, std::pair{"height", &s.new_height_mm}}) {
    double value = size_from_mm(*mm, s.new_unit, dpi);
    ImGui::SetNextItemWidth(160.0f);
    if (ImGui::InputDouble(label, &value, 0.0, 0.0, format)) {
      *mm = size_in_mm(value, s.new_unit, dpi);
      s.new_standard = -1;  // typed: a custom size
    }
  }
  ImGui::SetNextItemWidth(160.0f);
  ImGui::InputFloat("DPI", &s.new_dpi, 10.0f, 50.0f, "%.0f");
  s.new_width = cells_across(s.new_width_mm, dpi);
  s.new_height = cells_across(s.new_height_mm, dpi);
  ImGui::TextDisabled("%d x %d cells, %.0f x %.0f mm", s.new_width, s.new_height, s.new_width_mm,
                      s.new_height_mm);
}

void file_menu(PanelContext& c) {
  WindowState& s = c.state;
  const bool unsaved = c.worker.stats().events_since_save > 0;
  bool open_new = false;
  std::optional<FilePurpose> browse;
  // An action that would discard paint runs at once when nothing is unsaved, else after the
  // prompt (opened below, at the top level of the ID stack, not inside a menu or popup).
  auto ask = [&](PendingAction action, std::filesystem::path path = {}) {
    s.pending = action;
    s.pending_path = std::move(path);
    s.pending_confirmed = !unsaved;
    s.ask_unsaved = unsaved;
  };
  auto save = [&] {
    if (s.file) {
      c.files.save(*s.file);
    } else {
      browse = FilePurpose::kSavePainting;
    }
  };
  // A shortcut's file command, unless a dialog is up (it has the keyboard).
  std::optional<Command> command = take_file_command(s.commands);
  // (Quit, from the window's close button too, always gets through: its prompt replaces the
  // dialog.)
  if (command != Command::kQuit &&
      (s.file_browser.is_open() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))) {
    command.reset();
  }
  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::BeginMenu("File")) {
      if (ImGui::MenuItem("New...", keys(Command::kNew))) command = Command::kNew;
      if (ImGui::MenuItem("Open...", keys(Command::kOpen))) command = Command::kOpen;
      if (ImGui::BeginMenu("Open recent", !s.recent.empty())) {
        for (std::size_t i = 0; i < s.recent.size(); ++i) {
          const auto& file = s.recent[i];
          ImGui::PushID(static_cast<int>(i));  // two names may read alike once escaped
          if (ImGui::MenuItem(files::terminal_text(file.string()).c_str()))
            ask(PendingAction::kOpenRecent, file);
          ImGui::PopID();
        }
        ImGui::EndMenu();
      }
      ImGui::Separator();
      if (ImGui::MenuItem("Save", keys(Command::kSave))) command = Command::kSave;
      if (ImGui::MenuItem("Save as...", keys(Command::kSaveAs))) command = Command::kSaveAs;
      if (ImGui::MenuItem("Export image...")) command = Command::kExportImage;
      if (ImGui::MenuItem("Export time-lapse...")) command = Command::kExportTimelapse;
      ImGui::Separator();
      if (ImGui::MenuItem("Quit")) command = Command::kQuit;
      ImGui::EndMenu();
    }
    edit_menu(s, c.worker, c.painting.undo_depth, c.painting.redo_depth);
    if (ImGui::BeginMenu("View")) {
      if (ImGui::MenuItem("Fit canvas", keys(Command::kFitCanvas))) s.fit_requested = true;
      if (ImGui::MenuItem("One cell per pixel", keys(Command::kOneCellPerPixel)))
        s.view.pixels_per_cell = 1.0;
      if (ImGui::MenuItem("Reset rotation")) s.view.rotation_rad = 0.0;
      ImGui::Separator();
      if (ImGui::MenuItem("Reference image...")) browse = FilePurpose::kOpenReference;
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }
  if (command) {
    switch (*command) {
      case Command::kNew:
        open_new = true;
        break;
      case Command::kOpen:
        browse = FilePurpose::kOpenPainting;
        break;
      case Command::kSave:
        save();
        break;
      case Command::kSaveAs:
        browse = FilePurpose::kSavePainting;
        break;
      case Command::kExportImage:
        browse = FilePurpose::kExportImage;
        break;
      case Command::kExportTimelapse:
        s.timelapse_requested = true;  // the window opens its dialog (timelapse_export.hpp)
        break;
      case Command::kQuit:
        ask(PendingAction::kQuit);
        break;
      default:
        break;
    }
  }
  if (open_new) ImGui::OpenPopup("New painting");
  if (browse) s.file_browser.open(browser_request(*browse, s));

  if (ImGui::BeginPopupModal("New painting", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    new_painting_size(s);
    if (ImGui::Button("Create")) {
      ImGui::CloseCurrentPopup();
      ask(PendingAction::kNew);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }

  unsaved_prompt(c);
  changed_on_disk_prompt(c);

  const FileBrowserResult chosen = s.file_browser.draw();
  const bool continuing = std::exchange(
      s.continue_after_save, s.continue_after_save && chosen.kind == FileBrowserResult::kNone);
  if (chosen.kind == FileBrowserResult::kChosen) {
    switch (chosen.purpose) {
      case FilePurpose::kOpenPainting:
        ask(PendingAction::kOpen, chosen.file);
        break;
      case FilePurpose::kSavePainting: {
        // The dialog asked before replacing a file that is there.
        const bool saved = c.files.save_over(chosen.file);
        // Saved for the prompt's sake: its action goes on; not saved: nothing is discarded.
        if (continuing && saved) s.pending_confirmed = true;
        if (continuing && !saved) s.pending = PendingAction::kNone;
        break;
      }
      case FilePurpose::kExportImage:
        c.files.export_image(chosen.file);
        break;
      case FilePurpose::kOpenStrokes:
        break;
      case FilePurpose::kOpenReference:
        s.reference_requested = chosen.file;  // the window opens it (reference_image.hpp)
        break;
    }
  } else if (chosen.kind == FileBrowserResult::kCancelled && continuing) {
    s.pending = PendingAction::kNone;  // Save as cancelled: so is the action it was for
  }
}

// A colour chip with its explanation as the tooltip.
void chip(const char* id, const std::array<float, 3>& rgb, float size, const char* tooltip) {
  ImGui::ColorButton(id, rgba(rgb), ImGuiColorEditFlags_NoTooltip, ImVec2(size, size));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

void palette_panel(PanelContext& c) {
  WindowState& s = c.state;
  const auto& pigments = data::PigmentDatabase::defaults().all();
  if (s.mix_parts.size() != pigments.size()) s.mix_parts.assign(pigments.size(), 0.0f);
  if (!ImGui::CollapsingHeader("Palette", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool any = false;
  for (float p : s.mix_parts) any = any || p > 0.0f;
  // The swatch: the mix as a stroke with this brush and load leaves it on the canvas, beside
  // its masstone (session/swatch.hpp).
  char on_canvas_tip[160];
  std::snprintf(on_canvas_tip, sizeof on_canvas_tip,
                "on canvas: a stroke with this brush, load and pressure,\nas rendered "
                "(median wet thickness %.2f mm)",
                s.swatch_thickness_mm);
  // No parts (a cleared mix): neutral chips, not the last mix's colours.
  constexpr std::array<float, 3> kNoMix{0.5f, 0.5f, 0.5f};
  constexpr const char* kNoMixTip = "no mix: give pigments parts below";
  chip("##on_canvas", any ? s.swatch_on_canvas_rgb : kNoMix, 48.0f,
       any ? on_canvas_tip : kNoMixTip);
  ImGui::SameLine();
  chip("##masstone", any ? s.swatch_masstone_rgb : kNoMix, 48.0f,
       any ? "masstone: the mix, opaque" : kNoMixTip);
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::SetNextItemWidth(120.0f);
  ImGui::SliderFloat("mm³", &s.load_volume_mm3, static_cast<float>(kLoadMinMm3),
                     static_cast<float>(kLoadMaxMm3), "%.0f", ImGuiSliderFlags_Logarithmic);
  ImGui::SetNextItemWidth(120.0f);
  if (ImGui::BeginCombo("body", s.paint_body.c_str())) {
    for (const paintcore::PaintBodyInfo& body : paintcore::kPaintBodies) {
      const std::string name(body.name);
      if (ImGui::Selectable(name.c_str(), name == s.paint_body)) s.paint_body = name;
    }
    ImGui::EndCombo();
  }
  // (Two lines either way: a line more once pigments are chosen moved every control below,
  // and a pointer aimed at them landed on the row above.)
  if (!any) {
    ImGui::TextDisabled("on canvas");
    ImGui::TextDisabled("| masstone");
  } else {
    ImGui::Text("on canvas %.2f mm%s", s.swatch_thickness_mm, s.swatch_busy ? " ..." : "");
    ImGui::TextUnformatted("| masstone");
  }
  ImGui::EndGroup();
  ImGui::Checkbox("wipe first", &s.wipe_before_load);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Load onto a clean brush: paint still on it is wiped off first");
  ImGui::SameLine();
  ImGui::BeginDisabled(!any);
  if (ImGui::Button("Load brush")) load_palette_mix(s, c.worker, c.painting.brush_volume_mm3);
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Wipe")) c.worker.submit(input::WipeEvent{});
  ImGui::SameLine();
  if (ImGui::Button("Clear mix")) {
    std::fill(s.mix_parts.begin(), s.mix_parts.end(), 0.0f);
    s.mix_changed = true;
  }
  ImGui::Text("on brush: %.1f mm³", c.painting.brush_volume_mm3);
  ImGui::SameLine();  // on this line: a row more would move every control below
  medium_choice(s);
  if (!s.swatch_error.empty()) ImGui::TextWrapped("swatch: %s", s.swatch_error.c_str());
  // Each pigment: its masstone and a layer as thick as the swatch's deposit, then its parts.
  char layer_tip[96];
  std::snprintf(layer_tip, sizeof layer_tip, "a %.2f mm layer over the ground",
                s.swatch_thickness_mm > 0.0 ? s.swatch_thickness_mm : 0.1);
  ImGui::BeginChild("pigments", ImVec2(0, 180), true);
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    if (i < s.pigment_masstone_rgb.size() && i < s.pigment_layer_rgb.size()) {
      chip("##masstone", s.pigment_masstone_rgb[i], ImGui::GetFrameHeight(), "masstone");
      ImGui::SameLine(0.0f, 1.0f);
      chip("##layer", s.pigment_layer_rgb[i], ImGui::GetFrameHeight(), layer_tip);
      ImGui::SameLine();
    }
    ImGui::SetNextItemWidth(90.0f);
    if (ImGui::SliderFloat("##parts", &s.mix_parts[i], 0.0f, 10.0f, "%.1f")) s.mix_changed = true;
    ImGui::SameLine();
    ImGui::TextUnformatted(pigments[i].name.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
}

void brush_panel(PanelContext& c) {
  WindowState& s = c.state;
  if (!ImGui::CollapsingHeader("Brush", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool changed = false;
  if (ImGui::BeginCombo("head", s.brush.head.c_str())) {
    for (const auto& head : s.brush_heads) {
      if (ImGui::Selectable(head.c_str(), head == s.brush.head)) {
        s.brush.head = head;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  // The engine's range, up to the widest this canvas's cells hold (typed with Ctrl+click too).
  const double widest =
      c.painting.dpi > 0.0 ? paintcore::max_brush_size_mm(25.4 / c.painting.dpi) : kBrushSizeMaxMm;
  float size = static_cast<float>(s.brush.size_mm);
  if (ImGui::SliderFloat("size (mm)", &size, static_cast<float>(kBrushSizeMinMm),
                         static_cast<float>(widest), "%.1f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    s.brush.size_mm = size;
  }
  changed = changed || ImGui::IsItemDeactivatedAfterEdit();
  float stiffness = static_cast<float>(s.brush.stiffness);
  if (ImGui::SliderFloat("stiffness", &stiffness, 0.0f, 1.0f)) s.brush.stiffness = stiffness;
  changed = changed || ImGui::IsItemDeactivatedAfterEdit();
  if (changed) {
    c.worker.submit(brush_event(s));
  }
  ImGui::Checkbox("pressure from speed", &s.pressure_from_speed);
  ImGui::BeginDisabled(s.pressure_from_speed);
  ImGui::SliderFloat("mouse pressure", &s.mouse_pressure, 0.05f, 1.0f);
  ImGui::EndDisabled();
  // Sent with the next pen sample (InputRouter::choose_quality), as the session records it.
  enum_combo("quality", s.quality, paintcore::kStepQualityNames);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "How finely the simulation steps the brush along its path. exact: a cell at a time;\n"
        "balanced: big brushes (64 cells and more) a sixteenth of their width; fast: an\n"
        "eighth from 32 cells, quicker on big brushes, with a faint ripple along the stroke.\n"
        "docs/simulation.md, Quality.");
  }
  ImGui::Checkbox("fast while behind", &s.catch_up);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "When the screen falls 150 ms behind the pen, take fast steps until it is back\n"
        "within 50 ms. Replay the session with `impasto replay --quality exact` to paint\n"
        "it again at full quality.");
  }
}

// The light's spectrum over the rendering range with the quadrature nodes marked.
void spectrum_plot(const WindowState& s, const render::SpectralPalette& palette) {
  static std::string plotted_light;
  static PlotSeries light{"light", {}, {}, IM_COL32(240, 240, 240, 255)};
  const auto& range = s.settings.range;
  if (plotted_light != s.settings.light) {
    plotted_light = s.settings.light;
    light.x.clear();
    light.y.clear();
    try {
      const data::Spectrum spd = data::light_from_spec(s.settings.light);
      for (double nm = range.first_nm; nm <= range.last_nm; nm += 5.0) {
        light.x.push_back(nm);
        light.y.push_back(spd.at(nm));
      }
    } catch (const std::exception&) {
    }
  }
  PlotOptions options;
  options.id = "##spectrum";
  options.title = "light spectrum, nodes";
  options.size = ImVec2(kPanelWidth - 20, 110);
  options.markers_x.assign(palette.sampling().wavelengths_nm.begin(),
                           palette.sampling().wavelengths_nm.end());
  const double hovered_nm = draw_plot(options, std::span(&light, 1));
  // The tooltip in nanometres: the light there and the nearest quadrature node.
  const auto& nodes = options.markers_x;
  if (!std::isnan(hovered_nm) && !nodes.empty()) {
    const auto nearest = std::min_element(nodes.begin(), nodes.end(), [&](double a, double b) {
      return std::abs(a - hovered_nm) < std::abs(b - hovered_nm);
    });
    ImGui::SetTooltip("%.1f nm\nlight: %.3g\nnearest node: %.1f nm (%d of %zu)", hovered_nm,
                      series_at(light, hovered_nm), *nearest,
                      static_cast<int>(nearest - nodes.begin()) + 1, nodes.size());
  }
}

// A disc: the centre is the light straight above, the rim the horizon; drag to move it.
bool direction_pad(WindowState& s) {
  const float radius = 55.0f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##direction", ImVec2(2 * radius, 2 * radius));
  const ImVec2 centre(origin.x + radius, origin.y + radius);
  bool changed = false;
  if (ImGui::IsItemActive()) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const double dx = (mouse.x - centre.x) / radius, dy = (mouse.y - centre.y) / radius;
    const double r = std::min(1.0, std::hypot(dx, dy));
    s.settings.light_azimuth_deg = std::atan2(dy, dx) * 180.0 / std::numbers::pi;
    s.settings.light_elevation_deg = std::max(5.0, 90.0 * (1.0 - r));
    changed = true;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddCircleFilled(centre, radius, IM_COL32(40, 40, 48, 255));
  draw->AddCircle(centre, radius, IM_COL32(150, 150, 160, 255));
  const double az = s.settings.light_azimuth_deg * std::numbers::pi / 180.0;
  const double r = radius * (1.0 - s.settings.light_elevation_deg / 90.0);
  draw->AddCircleFilled(ImVec2(centre.x + static_cast<float>(r * std::cos(az)),
                               centre.y + static_cast<float>(r * std::sin(az))),
                        kLightDotRadius,
                        IM_COL32(kLightDotColour[0], kLightDotColour[1], kLightDotColour[2], 255));
  return changed;
}

void light_panel(PanelContext& c) {
  WindowState& s = c.state;
  if (!ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool changed = false;
  changed |= ImGui::Checkbox("blackbody", &s.use_blackbody);
  if (s.use_blackbody) {
    ImGui::SliderFloat("kelvin", &s.kelvin, 1500.0f, 12000.0f, "%.0f K");
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  } else if (!s.illuminants.empty()) {
    s.illuminant = std::clamp(s.illuminant, 0, static_cast<int>(s.illuminants.size()) - 1);
    if (ImGui::BeginCombo("illuminant",
                          s.illuminants[static_cast<std::size_t>(s.illuminant)].c_str())) {
      for (std::size_t i = 0; i < s.illuminants.size(); ++i) {
        if (ImGui::Selectable(s.illuminants[i].c_str(), static_cast<int>(i) == s.illuminant)) {
          s.illuminant = static_cast<int>(i);
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
  }
  ImGui::SliderInt("wavelengths", &s.settings.wavelengths, 1, render::kMaxNodes);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::PushTextWrapPos(0.0f);  // the panel's width
  ImGui::TextDisabled("%s", render::describe_rule(c.palette.sampling()).c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "How the wavelengths and their weights were chosen, and for a rule trained on this\n"
        "palette its CIEDE2000 error on the palette's training paints (masstones, tints,\n"
        "glazes and pairs) against every nanometre: the colour this many wavelengths costs.");
  }
  // Chromatic adaptation, by its names in `impasto render --adaptation`: bradford maps the
  // light's white to the display's, as an eye adapted to the room sees it; none shows a warm
  // light warm.
  if (enum_combo("adaptation", s.settings.adaptation, render::kChromaticAdaptationNames))
    s.settings_changed = true;
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Chromatic adaptation, as impasto render --adaptation:\n"
        "bradford: the light's white looks white, as to an eye adapted to the room;\n"
        "none: a warm light such as A looks warm on the display.");
  }
  if (changed) {
    s.settings.light = s.use_blackbody ? "blackbody:" + std::to_string(static_cast<int>(s.kelvin))
                                       : s.illuminants[static_cast<std::size_t>(s.illuminant)];
    s.settings_changed = true;
  }
  spectrum_plot(s, c.palette);
  const bool moved = direction_pad(s);
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::Text("azimuth %.0f°", s.settings.light_azimuth_deg);
  ImGui::Text("elevation %.0f°", s.settings.light_elevation_deg);
  ImGui::SetNextItemWidth(120.0f);
  ImGui::SliderFloat("intensity", &s.view_options.light_intensity, 0.1f, 3.0f);
  float ambient = static_cast<float>(s.settings.ambient);
  ImGui::SetNextItemWidth(120.0f);
  if (ImGui::SliderFloat("ambient", &ambient, 0.0f, 1.0f)) s.settings.ambient = ambient;
  ImGui::EndGroup();
  (void)moved;  // direction, intensity and ambient are uniforms: no re-bake needed
}

// Cracks: shown or not, the far view's cavity model, and the zoom from which their insides
// show (all uniforms: no re-bake).
void cracks_panel(PanelContext& c) {
  WindowState& s = c.state;
  if (!ImGui::CollapsingHeader("Cracks")) return;
  ImGui::Checkbox("show cracks", &s.settings.cracks);
  // By the names of impasto render --crack-model: corrected (the measured table), gouffe.
  enum_combo("far view", s.settings.crack_model, cracks::kCavityModelNames);
  bool close_up = s.view_options.crack_close_up_min_pixels > 0.0f;
  if (ImGui::Checkbox("close-up when zoomed in", &close_up)) {
    s.view_options.crack_close_up_min_pixels = close_up ? 6.0f : 0.0f;
  }
  if (close_up) {
    ImGui::SliderFloat("from px/cell", &s.view_options.crack_close_up_min_pixels, 2.0f, 64.0f,
                       "%.0f", ImGuiSliderFlags_Logarithmic);
  }
}

// The pressure curve from 0 to 1, as the brush will feel the pen.
void pressure_plot(const TabletSettings& settings) {
  const input::PressureCurve curve = settings.pressure_curve();
  float values[33];
  for (int i = 0; i <= 32; ++i) values[i] = static_cast<float>(curve.apply(i / 32.0));
  ImGui::PlotLines("##pressure", values, 33, 0, "pen -> brush pressure", 0.0f, 1.0f,
                   ImVec2(kPanelWidth - 20, 70));
}

void tablet_panel(PanelContext& c) {
  WindowState& s = c.state;
  if (!ImGui::CollapsingHeader("Tablet")) return;
  if (s.tablets.empty()) {
    ImGui::TextWrapped(
        "No pen tablet is being read: the mouse paints. (Tablets are found "
        "when plugged in; see docs/hid.md for access rights.)");
  }
  for (const auto& tablet : s.tablets) {
    ImGui::BulletText("%s  %.0f x %.0f mm  (%s)", tablet.name.c_str(), tablet.area.width_mm,
                      tablet.area.height_mm, tablet.path.c_str());
  }
  int target = static_cast<int>(s.tablet.target);
  const char* targets[] = {"whole screen", "this window", "whole canvas"};
  ImGui::Combo("maps onto", &target, targets, 3);
  s.tablet.target = static_cast<TabletTarget>(target);
  ImGui::Checkbox("keep aspect ratio", &s.tablet.keep_aspect);
  ImGui::Checkbox("Bezier pressure curve", &s.tablet.bezier);
  if (s.tablet.bezier) {
    ImGui::SliderFloat2("point 1", &s.tablet.bezier_points[0], 0.0f, 1.0f);
    ImGui::SliderFloat2("point 2", &s.tablet.bezier_points[2], 0.0f, 1.0f);
  } else {
    ImGui::SliderFloat("gamma", &s.tablet.pressure_gamma, 0.2f, 5.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic);
  }
  pressure_plot(s.tablet);
  ImGui::Text("%llu tablet samples painted", static_cast<unsigned long long>(s.tablet_samples));
  if (!s.tablet_error.empty()) ImGui::TextWrapped("%s", s.tablet_error.c_str());
}

void layers_panel(PanelContext& c) {
  WindowState& s = c.state;
  if (!ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // Shown in percent; the dry event takes the fraction.
  float dry_percent = 100.0f * s.dry_fraction;
  if (ImGui::SliderFloat("dry", &dry_percent, 0.0f, 100.0f, "%.0f %%"))
    s.dry_fraction = std::clamp(dry_percent / 100.0f, 0.0f, 1.0f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Dry now dries this share of the wet paint, from the bottom up");
  ImGui::SameLine();
  if (ImGui::Button("Dry now")) c.worker.submit(input::DryEvent{s.dry_fraction});
  s.hidden_dry_layers.resize(c.painting.dry_layers, false);
  ImGui::TextUnformatted("wet layer (top)");
  for (std::size_t i = c.painting.dry_layers; i-- > 0;) {
    bool visible = !s.hidden_dry_layers[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Checkbox(("dry layer " + std::to_string(i + 1)).c_str(), &visible)) {
      s.hidden_dry_layers[i] = !visible;
      s.visibility_changed = true;
    }
    ImGui::PopID();
  }
}

void history_panel(PanelContext& c) {
  if (!ImGui::CollapsingHeader("History", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::BeginDisabled(c.painting.undo_depth == 0);
  const std::string undo = "Undo (" + shortcut_text(Command::kUndo) + ")";
  if (ImGui::Button(undo.c_str())) c.worker.submit(input::UndoEvent{});
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(c.painting.redo_depth == 0);
  const std::string redo = "Redo (" + shortcut_text(Command::kRedo) + ")";
  if (ImGui::Button(redo.c_str())) c.worker.submit(input::RedoEvent{});
  ImGui::EndDisabled();
  ImGui::Text("%zu %s to undo, %zu to redo", c.painting.undo_depth,
              c.painting.undo_depth == 1 ? "step" : "steps", c.painting.redo_depth);
}

// Totals turned into rates over the last whole second (per-frame counts read 0 between
// frames that change nothing, which is most of them).
struct PerSecond {
  double window_start_s = -1.0;
  long long at_start = 0;
  double rate = 0.0;
  double update(long long total, double now_s) {
    if (window_start_s < 0.0 || total < at_start) {
      window_start_s = now_s;
      at_start = total;
    } else if (now_s - window_start_s >= 1.0) {
      rate = static_cast<double>(total - at_start) / (now_s - window_start_s);
      window_start_s = now_s;
      at_start = total;
    }
    return rate;
  }
};

std::string per_second_text(double rate, const char* unit) {
  char text[48];
  if (rate >= 1e6) {
    std::snprintf(text, sizeof text, "%.1f M%s/s", rate / 1e6, unit);
  } else if (rate >= 1e3) {
    std::snprintf(text, sizeof text, "%.1f k%s/s", rate / 1e3, unit);
  } else {
    std::snprintf(text, sizeof text, "%.0f %s/s", rate, unit);
  }
  return text;
}

// The measured truth first: how long a pen event takes to reach the screen (its own time
// stamp to the swap that shows it, pointer_latency.hpp), then what the machine is doing.
void status_bar(PanelContext& c) {
  const WindowState& s = c.state;
  static PerSecond shaded, tiles;
  const ImGuiIO& io = ImGui::GetIO();
  const double now_s = ImGui::GetTime();
  const double shaded_per_s = shaded.update(s.pixels_shaded, now_s);
  const double tiles_per_s = tiles.update(s.tiles_uploaded, now_s);
  const float height = ImGui::GetFrameHeight() + 6.0f;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const session::SimStats sim = c.worker.stats();
  ImGui::TextUnformatted(
      (pen_to_screen_text(s.input_latency_ms, s.input_latency_p95_ms, s.input_behind_ms) +
       (s.catching_up ? ", catching up (fast steps)" : ""))
          .c_str());
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Median and 95th percentile over the last 100 pen samples shown: from each mouse or\n"
        "pen event's own time stamp to the buffer swap of the first frame that shows it,\n"
        "queued or not. \"behind\": the oldest sample the screen does not show yet.");
  }
  ImGui::SameLine();
  ImGui::Text(
      "| sim %.2f ms/event, %.0f%% busy, %zu queued | shaded %s, %s | %dx%d @ %.0f dpi "
      "| zoom %.2f | cell %.0f,%.0f",
      sim.last_event_ms, sim.busy_ms_per_s / 10.0, sim.queued,
      per_second_text(shaded_per_s, "px").c_str(), per_second_text(tiles_per_s, "tile").c_str(),
      c.painting.width_cells, c.painting.height_cells, c.painting.dpi, s.view.pixels_per_cell,
      s.cursor_cell[0], s.cursor_cell[1]);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "sim: the paint simulation, per pen event and its share of a core\n"
        "shaded: canvas pixels the GPU's K-M pass shaded, per second (the rest is cached)\n"
        "tiles: canvas tiles uploaded to the GPU per second\n"
        "last frame: %.1f ms on the UI thread, %.1f ms of it uploading",
        s.frame_ms, s.upload_ms);
  }
  ImGui::End();
}

}  // namespace

void draw_panels(PanelContext& context) {
  file_menu(context);
  const ImGuiIO& io = ImGui::GetIO();
  const float top = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kPanelWidth, top));
  ImGui::SetNextWindowSize(
      ImVec2(kPanelWidth, io.DisplaySize.y - top - ImGui::GetFrameHeight() - 6.0f));
  ImGui::Begin("Impasto", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  palette_panel(context);
  eyedropper_panel(context.state, context.worker);
  context.board.draw(context.state, context.worker);
  context.colour_target.draw(context.state, context.worker, context.painting.brush_volume_mm3);
  brush_panel(context);
  tablet_panel(context);
  light_panel(context);
  cracks_panel(context);
  surface_panel(context.state);
  layers_panel(context);
  history_panel(context);
  ImGui::End();
  status_bar(context);
  context.state.notifications.draw();
}

}  // namespace impasto::app::window
