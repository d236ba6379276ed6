#include "window/file_browser.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

// One ImGui identity for the dialog whatever its title ("title###id").
constexpr const char* kBrowserId = "###file_browser";
constexpr const char* kReplaceId = "Replace file?###file_browser_replace";

std::string size_text(std::uintmax_t bytes) {
  char text[32];
  if (bytes >= 1024u * 1024u) {
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  } else {
    std::snprintf(text, sizeof text, "%.0f KB", static_cast<double>(bytes) / 1024.0 + 0.5);
  }
  return text;
}

// A place's button: its name, the whole path as the tooltip.
bool place_button(const std::string& label, const fs::path& path) {
  const bool clicked = ImGui::Selectable((label + "##" + path.string()).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.string().c_str());
  return clicked;
}

std::string folder_label(const fs::path& folder) {
  const std::string name = folder.filename().string();
  return name.empty() ? folder.string() : name;
}

}  // namespace

FileBrowser::FileBrowser(fs::path folder_memory) : memory_(std::move(folder_memory)) {}

void FileBrowser::open(FileBrowserRequest request) {
  request_ = std::move(request);
  filters_ = filters_for(request_.purpose);
  filter_ = 0;
  name_ = proposed_file_name(request_.purpose, request_.painting);
  error_.clear();
  replace_.clear();
  open_requested_ = true;
  focus_name_ = true;
  navigate(starting_folder(memory_, request_.purpose, request_.painting));
}

void FileBrowser::navigate(const fs::path& folder) {
  folder_ = folder;
  folder_input_ = folder_.string();
  error_.clear();
  refresh();
}

void FileBrowser::refresh() {
  std::string error;
  entries_ = list_folder(folder_, filters_.at(filter_), show_hidden_, &error);
  if (!error.empty()) error_ = error;
}

FileBrowserResult FileBrowser::choose(const fs::path& file) {
  memory_.remember(request_.purpose, file.parent_path());
  open_ = false;
  ImGui::CloseCurrentPopup();
  return {FileBrowserResult::kChosen, request_.purpose, file};
}

FileBrowserResult FileBrowser::try_accept(const std::string& typed) {
  if (typed.empty()) return {};
  fs::path file = resolve_typed_path(folder_, typed);
  std::error_code code;
  if (fs::is_directory(file, code)) {
    navigate(file);
    name_ = proposed_file_name(request_.purpose, request_.painting);
    focus_name_ = true;
    return {};
  }
  if (!writes_file(request_.purpose)) {
    if (!fs::exists(file, code)) {
      error_ = "there is no file " + file.string();
      return {};
    }
    return choose(file);
  }
  file = with_filter_extension(file, filters_.at(filter_));
  if (!fs::is_directory(file.parent_path(), code)) {
    error_ = "there is no folder " + file.parent_path().string();
    return {};
  }
  if (fs::is_directory(file, code)) {
    navigate(file);
    return {};
  }
  if (fs::exists(file, code)) {
    replace_ = file;  // asked below, in the dialog
    return {};
  }
  return choose(file);
}

void FileBrowser::draw_places() {
  ImGui::TextDisabled("Places");
  if (place_button("Home", home_folder())) navigate(home_folder());
  if (request_.painting) {
    std::error_code code;
    const fs::path beside = fs::absolute(*request_.painting, code).parent_path();
    if (place_button("Painting's folder", beside)) navigate(beside);
  }
  if (place_button("/", fs::path("/"))) navigate("/");
  const std::vector<fs::path> remembered = memory_.folders();
  if (!remembered.empty()) {
    ImGui::Spacing();
    ImGui::TextDisabled("Last folders");
    for (const fs::path& folder : remembered) {
      if (place_button(folder_label(folder), folder)) navigate(folder);
    }
  }
  // Opening: the recent paintings themselves; saving: the folders they are in, each once.
  const bool opening = !writes_file(request_.purpose);
  std::vector<fs::path> shown = remembered, items;
  for (const fs::path& file : request_.recent_files) {
    const fs::path item = opening ? file : file.parent_path();
    if (std::find(shown.begin(), shown.end(), item) != shown.end()) continue;
    shown.push_back(item);
    items.push_back(file);
  }
  if (items.empty()) return;
  ImGui::Spacing();
  ImGui::TextDisabled("Recent");
  for (const fs::path& file : items) {
    const fs::path folder = file.parent_path();
    if (place_button(opening ? file.filename().string() : folder_label(folder),
                     opening ? file : folder)) {
      navigate(folder);
      if (opening) name_ = file.filename().string();
    }
  }
}

// The folder's entries; a double-clicked file (or Enter's) is returned in *accepted.
bool FileBrowser::draw_listing(std::string* accepted) {
  bool navigated = false;
  if (!ImGui::BeginTable(
          "##entries", 2,
          ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersOuter,
          ImVec2(0.0f, ImGui::GetContentRegionAvail().y))) {
    return false;
  }
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("Name", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("Size", ImGuiTableColumnFlags_WidthFixed, 80.0f);
  ImGui::TableHeadersRow();
  for (const FolderEntry& entry : entries_) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = entry.is_folder ? entry.name + "/" : entry.name;
    if (entry.is_folder) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(150, 190, 255, 255));
    const bool clicked = ImGui::Selectable(
        label.c_str(), !entry.is_folder && entry.name == name_,
        ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowDoubleClick);
    if (entry.is_folder) ImGui::PopStyleColor();
    if (clicked && entry.is_folder && ImGui::IsMouseDoubleClicked(0)) {
      const fs::path into = folder_ / entry.name;
      ImGui::EndTable();
      navigate(into);
      return true;
    }
    if (clicked && !entry.is_folder) {
      name_ = entry.name;
      if (ImGui::IsMouseDoubleClicked(0)) *accepted = entry.name;
    }
    ImGui::TableNextColumn();
    if (!entry.is_folder) ImGui::TextDisabled("%s", size_text(entry.size_bytes).c_str());
  }
  if (entries_.empty()) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextDisabled("(no folders or %s here)", filters_.at(filter_).label.c_str());
  }
  ImGui::EndTable();
  return navigated;
}

FileBrowserResult FileBrowser::draw() {
  const std::string popup = request_.title + kBrowserId;
  if (open_requested_) {
    ImGui::OpenPopup(popup.c_str());
    open_requested_ = false;
    open_ = true;
  }
  if (!open_) return {};
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 size(std::min(780.0f, io.DisplaySize.x - 40.0f),
                    std::min(500.0f, io.DisplaySize.y - 60.0f));
  ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  bool still_open = true;
  // Opaque: the panels behind must not show through the listing.
  ImVec4 background = ImGui::GetStyleColorVec4(ImGuiCol_PopupBg);
  background.w = 1.0f;
  ImGui::PushStyleColor(ImGuiCol_PopupBg, background);
  const bool shown =
      ImGui::BeginPopupModal(popup.c_str(), &still_open, ImGuiWindowFlags_NoSavedSettings);
  ImGui::PopStyleColor();
  if (!shown) {
    // Closed by its title bar's x.
    open_ = false;
    return {FileBrowserResult::kCancelled, request_.purpose, {}};
  }
  FileBrowserResult result;
  std::string accepted;

  // The folder: up, and a path to type (Ctrl+L, as in other file dialogs).
  if (ImGui::ArrowButton("##up", ImGuiDir_Up)) navigate(folder_.parent_path());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Parent folder");
  ImGui::SameLine();
  if (io.KeyCtrl && ImGui::IsKeyPressed('L')) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(-160.0f);
  // Enter, or leaving the field after typing in it, goes to the folder typed.
  const bool entered =
      ImGui::InputText("##folder", &folder_input_,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  if (entered || (ImGui::IsItemDeactivated() && folder_input_ != folder_.string())) {
    const fs::path typed = resolve_typed_path(folder_, folder_input_);
    std::error_code code;
    if (fs::is_directory(typed, code)) {
      navigate(typed);
      focus_name_ = entered;
    } else if (entered && fs::is_directory(typed.parent_path(), code)) {
      navigate(typed.parent_path());
      accepted = typed.filename().string();  // a file's path: as if its name were typed
    } else {
      error_ = "there is no folder " + typed.string();
    }
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type a folder and press Enter (Ctrl+L)");
  ImGui::SameLine();
  if (ImGui::Checkbox("hidden", &show_hidden_)) refresh();

  // Places on the left, the folder's entries on the right.
  const float bottom_h = ImGui::GetFrameHeightWithSpacing() * 2.0f + 8.0f +
                         (error_.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing() * 2.0f);
  const float body_h = std::max(80.0f, ImGui::GetContentRegionAvail().y - bottom_h);
  ImGui::BeginChild("##places", ImVec2(170.0f, body_h), true);
  draw_places();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("##listing", ImVec2(0.0f, body_h), false);
  draw_listing(&accepted);
  ImGui::EndChild();

  // The file's name, its type, and the buttons.
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 120, 110, 255));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("File name");
  ImGui::SameLine();
  if (focus_name_ && !ImGui::IsAnyItemActive()) {
    ImGui::SetKeyboardFocusHere();
    focus_name_ = false;
  }
  ImGui::SetNextItemWidth(-230.0f);
  if (ImGui::InputText("##name", &name_,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    accepted = name_;
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##type", filters_.at(filter_).label.c_str())) {
    for (std::size_t i = 0; i < filters_.size(); ++i) {
      if (ImGui::Selectable(filters_[i].label.c_str(), i == filter_)) {
        filter_ = i;
        // The name follows the type (picture.png -> picture.exr).
        if (!name_.empty()) name_ = with_filter_extension(name_, filters_[i]).string();
        refresh();
      }
    }
    ImGui::EndCombo();
  }
  const float button_w = 90.0f;
  ImGui::SetCursorPosX(ImGui::GetWindowContentRegionMax().x - 2.0f * button_w -
                       ImGui::GetStyle().ItemSpacing.x);
  if (ImGui::Button("Cancel", ImVec2(button_w, 0.0f)) ||
      (replace_.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))) {
    open_ = false;
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return {FileBrowserResult::kCancelled, request_.purpose, {}};
  }
  ImGui::SameLine();
  if (ImGui::Button(request_.accept_label.c_str(), ImVec2(button_w, 0.0f))) accepted = name_;
  if (!accepted.empty()) result = try_accept(accepted);

  // Replacing a file asks first (a modal over the dialog).
  if (!replace_.empty() && !ImGui::IsPopupOpen(kReplaceId)) ImGui::OpenPopup(kReplaceId);
  if (ImGui::BeginPopupModal(kReplaceId, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextWrapped("%s already exists in %s.", replace_.filename().string().c_str(),
                       replace_.parent_path().string().c_str());
    ImGui::TextWrapped("Replace it?");
    ImGui::PopTextWrapPos();
    const fs::path file = replace_;
    if (ImGui::Button("Replace", ImVec2(button_w, 0.0f))) {
      replace_.clear();
      ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
      result = choose(file);  // closes the dialog too
      ImGui::EndPopup();
      return result;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel##replace", ImVec2(button_w, 0.0f)) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      replace_.clear();
      focus_name_ = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  ImGui::EndPopup();
  if (!still_open && result.kind == FileBrowserResult::kNone) {
    open_ = false;
    return {FileBrowserResult::kCancelled, request_.purpose, {}};
  }
  return result;
}

}  // namespace impasto::app::window
