#include "window/pigment_editor.hpp"

#include <impasto/data/colorimetry.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigment_text.hpp>
#include <impasto/data/pigment_user_layer.hpp>
#include <impasto/files/atomic_file.hpp>
#include <impasto/files/input_file.hpp>

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>

#include "pigment_curves.hpp"
#include "window/plot.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

constexpr ImU32 kK = IM_COL32(240, 90, 70, 255), kS = IM_COL32(90, 150, 255, 255),
                kRatio = IM_COL32(190, 120, 240, 255), kR = IM_COL32(110, 210, 120, 255);
constexpr ImU32 kSecond = IM_COL32(240, 240, 240, 255);
const char* const kMetadataKeys[] = {"colour_index", "binder",  "product",
                                     "source",       "licence", "units"};
// Keys the editor does not offer: written by the program.
bool derived_key(const std::string& key) {
  return key == "name" || key == "quantity" || key == "flakes" || key == "modified" ||
         key == "fitted_from";
}

ImVec4 colour_of(const std::array<double, 3>& srgb) {
  return ImVec4(static_cast<float>(srgb[0]), static_cast<float>(srgb[1]),
                static_cast<float>(srgb[2]), 1.0f);
}

bool contains_ignoring_case(const std::string& text, const char* part) {
  std::string a = text, b = part;
  for (auto* s : {&a, &b})
    std::transform(s->begin(), s->end(), s->begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return a.find(b) != std::string::npos;
}

struct Curves {
  PlotSeries k, s, ratio, r;
};
Curves curves_of(const data::Pigment& p, const std::string& suffix, bool dashed = false) {
  const PigmentCurves c = pigment_curves(p);
  return {{"K" + suffix, c.nm, c.k, kK, dashed},
          {"S" + suffix, c.nm, c.s, kS, dashed},
          {"K/S" + suffix, c.nm, c.k_over_s, kRatio, dashed},
          {"R" + suffix, c.nm, c.r_infinite, kR, dashed}};
}

// Below two plots of `half_width` side by side: R-infinity across both, on 0..1.
void draw_r_infinity_plot(PlotOptions o, const char* id, const char* title, float half_width,
                          std::span<const PlotSeries> series) {
  o.id = id;
  o.title = title;
  o.y_max = 1.0;
  o.size = ImVec2(2 * half_width + 8, 140);
  draw_plot(o, series);
}

// The user layer's pigment files and their contents.
std::map<fs::path, std::string> snapshot_folder(const fs::path& folder) {
  std::map<fs::path, std::string> files;
  std::error_code error;
  if (!fs::is_directory(folder, error)) return files;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.path().extension() == ".csv" && entry.is_regular_file())
      files.emplace(entry.path(), files::read_whole_file(entry.path(), "pigment file"));
  }
  return files;
}

}  // namespace

void PigmentEditor::open(const std::string& pigment) {
  open_ = true;
  selected_ = pigment;
}

const std::vector<render::SwatchColour>& PigmentEditor::swatches_of(const data::Pigment& pigment) {
  auto it = swatches_.find(pigment.name);
  if (it != swatches_.end()) return it->second;
  std::vector<render::SwatchColour> colours;
  try {
    const data::PigmentDatabase& db = library_->database();
    colours = render::standard_swatches(pigment, db.get("White"), data::light_from_spec(light_));
  } catch (const std::exception&) {
  }
  return swatches_.emplace(pigment.name, std::move(colours)).first->second;
}

template <typename F>
void PigmentEditor::change(const std::string& what, F&& apply) {
  const fs::path folder = library_->user_folder();
  try {
    if (folder.empty()) throw std::runtime_error("no user pigment folder (HOME is not set)");
    UndoStep step{what, snapshot_folder(folder)};
    apply(folder);
    undo_.push_back(std::move(step));
    message_ = what;
    message_is_error_ = false;
  } catch (const std::exception& e) {
    message_ = e.what();
    message_is_error_ = true;
  }
  data::reload_active_pigment_library();
  editing_.clear();
  if (state_) state_->mix_changed = true;  // the palette's chips
}

void PigmentEditor::undo() {
  if (undo_.empty()) return;
  library_ = &data::active_pigment_library();
  const UndoStep step = std::move(undo_.back());
  undo_.pop_back();
  const fs::path folder = library_->user_folder();
  try {
    for (const auto& [path, contents] : snapshot_folder(folder))
      if (!step.files.count(path)) fs::remove(path);
    for (const auto& [path, contents] : step.files) files::write_file_atomically(path, contents);
    message_ = "undone: " + step.what;
    message_is_error_ = false;
  } catch (const std::exception& e) {
    message_ = std::string("undo failed: ") + e.what();
    message_is_error_ = true;
  }
  data::reload_active_pigment_library();
  editing_.clear();
  if (state_) state_->mix_changed = true;
}

void PigmentEditor::list_panel() {
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##search", "search", search_, sizeof search_);
  ImGui::BeginChild("##pigments", ImVec2(0, 0), true);
  const auto& all = library_->database().all();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const data::Pigment& p = all[i];
    const std::string& layer = library_->origins()[i].layer;
    if (search_[0] && !contains_ignoring_case(p.name, search_) &&
        !contains_ignoring_case(layer, search_))
      continue;
    ImGui::PushID(static_cast<int>(i));
    const auto& colours = swatches_of(p);
    const ImVec4 chip = colours.empty() ? ImVec4(0.5f, 0.5f, 0.5f, 1) : colour_of(colours[0].srgb);
    ImGui::ColorButton("##chip", chip, ImGuiColorEditFlags_NoTooltip,
                       ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
    ImGui::SameLine();
    // The name is clipped before the layer's column.
    const float layer_x = ImGui::GetWindowContentRegionMax().x - 62;
    if (ImGui::Selectable(p.name.c_str(), p.name == selected_, 0,
                          ImVec2(layer_x - ImGui::GetCursorPosX() - 4, ImGui::GetFrameHeight())))
      selected_ = p.name;
    ImGui::SameLine(layer_x);
    ImGui::TextDisabled("%s", layer.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
}

void PigmentEditor::curves_tab(const data::Pigment& pigment, const std::vector<double>& nodes) {
  const Curves c = curves_of(pigment, "");
  const float w = (ImGui::GetContentRegionAvail().x - 8) / 2;
  PlotOptions o;
  o.markers_x = nodes;
  o.size = ImVec2(w, 150);
  o.id = "##ks";
  o.title = "K and S";
  const PlotSeries ks[] = {c.k, c.s};
  draw_plot(o, ks);
  ImGui::SameLine();
  o.id = "##ratio";
  o.title = "K/S";
  draw_plot(o, std::span(&c.ratio, 1));
  draw_r_infinity_plot(o, "##r", "R-infinity (opaque layer)", w, std::span(&c.r, 1));
  ImGui::Text("Swatches under %s (sRGB; hover for L*a*b*)", light_.c_str());
  for (const auto& colour : swatches_of(pigment)) {
    ImGui::BeginGroup();
    ImGui::ColorButton(colour.label.c_str(), colour_of(colour.srgb), ImGuiColorEditFlags_NoTooltip,
                       ImVec2(88, 48));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s\nL* %.2f a* %.2f b* %.2f\nX %.3f Y %.3f Z %.3f", colour.label.c_str(),
                        colour.lab.L, colour.lab.a, colour.lab.b, colour.xyz.X, colour.xyz.Y,
                        colour.xyz.Z);
    ImGui::TextUnformatted(colour.label.c_str());
    ImGui::EndGroup();
    ImGui::SameLine();
  }
  ImGui::NewLine();
}

void PigmentEditor::metadata_tab(const data::Pigment& pigment, bool in_user_layer) {
  if (editing_ != pigment.name) {
    editing_ = pigment.name;
    std::snprintf(edit_name_.data(), edit_name_.size(), "%s", pigment.name.c_str());
    edit_fields_.clear();
    for (const char* key : kMetadataKeys) edit_fields_.push_back({key, {}});
    for (const auto& [key, value] : pigment.metadata) {
      if (derived_key(key)) continue;
      auto field = std::find_if(edit_fields_.begin(), edit_fields_.end(),
                                [&](const auto& f) { return f.first == key; });
      if (field == edit_fields_.end()) field = edit_fields_.insert(edit_fields_.end(), {key, {}});
      std::snprintf(field->second.data(), field->second.size(), "%s", value.c_str());
    }
  }
  ImGui::BeginDisabled(!in_user_layer);
  ImGui::InputText("name", edit_name_.data(), edit_name_.size());
  // Inline validation: what a save would refuse, said before it is tried.
  const std::string name = edit_name_.data();
  std::string problem;
  if (name.empty()) problem = "a pigment needs a name";
  const data::Pigment* same = library_->database().find(name);
  if (problem.empty() && name != pigment.name && same && same->name == name)
    problem = "'" + name + "' is already in the library (" + library_->origin(name)->layer + ")";
  if (!problem.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", problem.c_str());
  for (auto& [key, value] : edit_fields_) ImGui::InputText(key.c_str(), value.data(), value.size());
  ImGui::SetNextItemWidth(160);
  ImGui::InputTextWithHint("##newkey", "new key", new_key_, sizeof new_key_);
  ImGui::SameLine();
  const std::string key = new_key_;
  const bool key_ok =
      !key.empty() && key.find_first_of(":\n\r#") == std::string::npos && !derived_key(key);
  ImGui::BeginDisabled(!key_ok);
  if (ImGui::Button("Add key")) {
    edit_fields_.push_back({key, {}});
    new_key_[0] = '\0';
  }
  ImGui::EndDisabled();
  if (!key.empty() && !key_ok)
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1),
                       "a key has no ':', '#' or line break and is "
                       "not one the program writes");
  ImGui::BeginDisabled(!problem.empty());
  if (ImGui::Button("Save")) {
    data::Pigment edited = pigment;
    edited.name = name;
    for (auto it = edited.metadata.begin(); it != edited.metadata.end();)
      it = derived_key(it->first) ? std::next(it) : edited.metadata.erase(it);
    for (const auto& [k, v] : edit_fields_)
      if (v[0]) edited.metadata[k] = v.data();
    edited.metadata["modified"] = data::utc_timestamp() + " in the Pigment editor";
    const std::string old_name = pigment.name;
    change("saved " + name, [&](const fs::path& folder) {
      const fs::path old_file = data::pigment_file_in_folder(folder, old_name);
      const fs::path written = data::save_pigment_to_folder(folder, edited, name == old_name);
      if (written != old_file && name != old_name) fs::remove(old_file);
    });
    selected_ = name;
  }
  ImGui::EndDisabled();
  ImGui::EndDisabled();
  if (!in_user_layer)
    ImGui::TextDisabled("The %s layer is read-only: duplicate it into your library to edit.",
                        library_->origin(pigment.name)->layer.c_str());
}

void PigmentEditor::import_tab() {
  ImGui::TextWrapped(
      "A pigment CSV (docs/pigments.md): '# quantity: kubelka_munk', '# name:', "
      "columns K and S.");
  ImGui::SetNextItemWidth(420);
  if (ImGui::InputText("file", import_path_, sizeof import_path_)) import_check_.clear();
  ImGui::SameLine();
  if (ImGui::Button("Check")) {
    try {
      const data::Pigment p = data::read_pigment_file(import_path_);
      import_check_ = "ok: '" + p.name + "', " + std::to_string(p.K.values.size()) +
                      " wavelengths " + std::to_string(int(p.K.wavelengths_nm.front())) + "-" +
                      std::to_string(int(p.K.wavelengths_nm.back())) + " nm";
    } catch (const std::exception& e) {
      import_check_ = e.what();
    }
  }
  if (!import_check_.empty()) {
    const bool ok = import_check_.rfind("ok:", 0) == 0;
    ImGui::TextColored(ok ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.4f, 0.4f, 1), "%s",
                       import_check_.c_str());
  }
  if (ImGui::Button("Import to my library")) import_file(import_path_);
}

void PigmentEditor::import_file(const fs::path& file) {
  library_ = &data::active_pigment_library();
  std::string imported;
  change("imported " + file.filename().string(), [&](const fs::path& folder) {
    imported = data::read_pigment_file(file).name;
    data::import_pigment_file(folder, file, false);
  });
  if (!imported.empty() && !message_is_error_) selected_ = imported;
}

void PigmentEditor::compare_tab(const data::Pigment& pigment, const std::vector<double>& nodes) {
  const auto& all = library_->database().all();
  ImGui::SetNextItemWidth(300);
  if (ImGui::BeginCombo("compare with", compare_with_.c_str())) {
    for (const auto& p : all)
      if (ImGui::Selectable(p.name.c_str(), p.name == compare_with_)) compare_with_ = p.name;
    ImGui::EndCombo();
  }
  const data::Pigment* other = library_->database().find(compare_with_);
  if (other == nullptr) return;
  const Curves a = curves_of(pigment, " " + pigment.name.substr(0, 14));
  const Curves b = curves_of(*other, " " + other->name.substr(0, 14), true);
  const float w = (ImGui::GetContentRegionAvail().x - 8) / 2;
  PlotOptions o;
  o.markers_x = nodes;
  o.size = ImVec2(w, 160);
  // One curve of each pigment, the other's in kSecond.
  const auto pair = [](const PlotSeries& first, PlotSeries second) {
    second.colour = kSecond;
    return std::array<PlotSeries, 2>{first, std::move(second)};
  };
  o.id = "##cmp_k";
  o.title = "K";
  draw_plot(o, pair(a.k, b.k));
  ImGui::SameLine();
  o.id = "##cmp_s";
  o.title = "S";
  draw_plot(o, pair(a.s, b.s));
  draw_r_infinity_plot(o, "##cmp_r", "R-infinity", w, pair(a.r, b.r));
  const auto& ca = swatches_of(pigment);
  const auto& cb = swatches_of(*other);
  if (ImGui::BeginTable("##cmp", 4, ImGuiTableFlags_Borders)) {
    ImGui::TableSetupColumn("swatch");
    ImGui::TableSetupColumn(pigment.name.c_str());
    ImGui::TableSetupColumn(other->name.c_str());
    ImGui::TableSetupColumn("dE00");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < ca.size() && i < cb.size(); ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(ca[i].label.c_str());
      ImGui::TableNextColumn();
      ImGui::ColorButton("##a", colour_of(ca[i].srgb), 0, ImVec2(40, 16));
      ImGui::TableNextColumn();
      ImGui::ColorButton("##b", colour_of(cb[i].srgb), 0, ImVec2(40, 16));
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", data::ciede2000(ca[i].lab, cb[i].lab));
    }
    ImGui::EndTable();
  }
}

void PigmentEditor::draw(WindowState& state, const render::SpectralPalette& palette) {
  state_ = &state;
  if (ImGui::BeginMainMenuBar()) {  // appends to the window's menu bar
    if (ImGui::BeginMenu("Pigments")) {
      ImGui::MenuItem("Pigment editor", nullptr, &open_);
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }
  if (!open_) return;
  const data::PigmentLibrary& library = data::active_pigment_library();
  if (&library != library_ || light_ != state.settings.light) {
    library_ = &library;
    light_ = state.settings.light;
    swatches_.clear();
  }
  ImGui::SetNextWindowSize(ImVec2(980, 660), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImVec2(20, 40), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Pigment editor", &open_)) {
    ImGui::End();
    return;
  }
  if (library_->database().find(selected_) == nullptr)
    selected_ = library_->database().all().front().name;
  const data::Pigment& pigment = library_->database().get(selected_);
  const data::LibraryPigment* origin = library_->origin(pigment.name);
  const bool in_user_layer = origin && origin->layer == "user";

  ImGui::BeginChild("##left", ImVec2(270, 0));
  list_panel();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::Text("%s", pigment.name.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%s layer, %s", origin ? origin->layer.c_str() : "?",
                      origin ? origin->file.filename().string().c_str() : "");
  // Library actions.
  if (ImGui::Button("Duplicate")) {
    std::string name = pigment.name + " copy";
    for (int n = 2; library_->database().find(name); ++n)
      name = pigment.name + " copy " + std::to_string(n);
    data::Pigment copy = pigment;
    copy.name = name;
    copy.metadata["modified"] = data::utc_timestamp() + " copied from " + pigment.name;
    change("duplicated " + pigment.name + " as " + name,
           [&](const fs::path& folder) { data::save_pigment_to_folder(folder, copy, false); });
    if (!message_is_error_) selected_ = name;
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!in_user_layer);
  if (ImGui::Button("Delete")) {
    const std::string name = pigment.name;
    change("deleted " + name,
           [&](const fs::path& folder) { data::remove_pigment_from_folder(folder, name); });
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(undo_.empty());
  if (ImGui::Button("Undo")) undo();
  if (!undo_.empty() && ImGui::IsItemHovered())
    ImGui::SetTooltip("undo: %s", undo_.back().what.c_str());
  ImGui::EndDisabled();
  if (!message_.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(message_is_error_ ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1),
                       "%s", message_.c_str());
  }
  std::vector<double> nodes(palette.sampling().wavelengths_nm.begin(),
                            palette.sampling().wavelengths_nm.end());
  const auto tab_flags = [&](Tab tab) {
    return pending_tab_ == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
  };
  if (ImGui::BeginTabBar("##tabs")) {
    if (ImGui::BeginTabItem("Curves", nullptr, tab_flags(Tab::curves))) {
      curves_tab(library_->database().get(selected_), nodes);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Metadata", nullptr, tab_flags(Tab::metadata))) {
      metadata_tab(library_->database().get(selected_), in_user_layer);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Import", nullptr, tab_flags(Tab::import))) {
      import_tab();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Fit", nullptr, tab_flags(Tab::fit))) {
      fit_.draw([&](const std::vector<data::Pigment>& pigments, bool overwrite) {
        change("saved " + std::to_string(pigments.size()) + " fitted pigments",
               [&](const fs::path& folder) {
                 for (data::Pigment p : pigments) {
                   // Metadata of the pigment it replaces is kept (binder, licence, source...).
                   if (const data::Pigment* old = library_->database().find(p.name))
                     for (const auto& [k, v] : old->metadata)
                       if (!derived_key(k) && k != "units" && k != "interface")
                         p.metadata.try_emplace(k, v);
                   p.metadata["fitted_from"] += " (" + data::utc_timestamp() + ")";
                   data::save_pigment_to_folder(folder, p, overwrite);
                 }
               });
      });
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Compare", nullptr, tab_flags(Tab::compare))) {
      compare_tab(library_->database().get(selected_), nodes);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    pending_tab_.reset();
  }
  ImGui::EndGroup();
  ImGui::End();
}

}  // namespace impasto::app::window
