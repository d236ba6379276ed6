#include "window/notifications.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>

namespace impasto::app::window {
namespace {

constexpr float kNoteWidth = 440.0f;

ImU32 note_colour(NoteLevel level) {
  switch (level) {
    case NoteLevel::kError:
      return IM_COL32(120, 28, 28, 240);
    case NoteLevel::kWarning:
      return IM_COL32(112, 84, 16, 240);
    case NoteLevel::kInfo:
      return IM_COL32(40, 44, 56, 230);
  }
  return IM_COL32(40, 44, 56, 230);
}

const char* note_label(NoteLevel level) {
  switch (level) {
    case NoteLevel::kError:
      return "Error";
    case NoteLevel::kWarning:
      return "Warning";
    case NoteLevel::kInfo:
      return "";
  }
  return "";
}

}  // namespace

double Notifications::now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void Notifications::post(NoteLevel level, std::string text, double at_s) {
  if (text.empty()) return;
  for (Note& note : notes_) {
    if (note.level == level && note.text == text) {
      ++note.repeats;
      note.posted_s = at_s;
      return;
    }
  }
  notes_.push_back({next_id_++, level, std::move(text), at_s, 1});
  while (notes_.size() > kMaxNotes) {
    const auto info = std::find_if(notes_.begin(), notes_.end(),
                                   [](const Note& n) { return n.level == NoteLevel::kInfo; });
    notes_.erase(info != notes_.end() ? info : notes_.begin());
  }
}

void Notifications::dismiss(std::uint64_t id) {
  std::erase_if(notes_, [id](const Note& n) { return n.id == id; });
}

void Notifications::expire(double at_s) {
  std::erase_if(notes_, [at_s](const Note& n) {
    return n.level == NoteLevel::kInfo && at_s - n.posted_s > kInfoSeconds;
  });
}

void Notifications::draw() {
  expire(now_s());
  if (notes_.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const ImGuiStyle& style = ImGui::GetStyle();
  // Lower left, above the status bar, over the canvas (the panels are on the right).
  const float status_h = ImGui::GetFrameHeight() + 6.0f;
  const float width = std::min(kNoteWidth, std::max(200.0f, io.DisplaySize.x - 380.0f));
  ImGui::SetNextWindowPos(ImVec2(10.0f, io.DisplaySize.y - status_h - 10.0f), ImGuiCond_Always,
                          ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, io.DisplaySize.y * 0.8f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin("##notifications", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoBackground);
  ImGui::PopStyleVar();
  std::uint64_t dismissed = 0;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const Note& note : notes_) {
    ImGui::PushID(static_cast<int>(note.id));
    draw->ChannelsSplit(2);
    draw->ChannelsSetCurrent(1);
    const ImVec2 top_left = ImGui::GetCursorScreenPos();
    ImGui::BeginGroup();
    ImGui::Dummy(ImVec2(0.0f, 2.0f));
    ImGui::Indent(6.0f);
    const float close_w = ImGui::CalcTextSize("x").x + style.FramePadding.x * 2.0f;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width - close_w - 3.0f * style.ItemSpacing.x -
                           12.0f);
    const char* label = note_label(note.level);
    if (*label) {
      ImGui::TextUnformatted(label);
      ImGui::SameLine();
    }
    if (note.repeats > 1) {
      ImGui::TextWrapped("%s (%d times)", note.text.c_str(), note.repeats);
    } else {
      ImGui::TextWrapped("%s", note.text.c_str());
    }
    ImGui::PopTextWrapPos();
    ImGui::Unindent(6.0f);
    ImGui::Dummy(ImVec2(0.0f, 2.0f));
    ImGui::EndGroup();
    const ImVec2 group_max = ImGui::GetItemRectMax();
    const ImVec2 bottom_right(top_left.x + width - style.WindowPadding.x * 2.0f, group_max.y);
    ImGui::SetCursorScreenPos(ImVec2(bottom_right.x - close_w - 4.0f, top_left.y + 2.0f));
    if (ImGui::SmallButton("x")) dismissed = note.id;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Dismiss");
    ImGui::SetCursorScreenPos(ImVec2(top_left.x, bottom_right.y + style.ItemSpacing.y));
    ImGui::Dummy(ImVec2(0.0f, 0.0f));
    draw->ChannelsSetCurrent(0);
    draw->AddRectFilled(top_left, bottom_right, note_colour(note.level), 4.0f);
    draw->ChannelsMerge();
    ImGui::PopID();
  }
  ImGui::End();
  if (dismissed) dismiss(dismissed);
}

}  // namespace impasto::app::window
