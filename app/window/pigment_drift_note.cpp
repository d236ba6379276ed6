#include "window/pigment_drift_note.hpp"

#include <impasto/data/pigment_library.hpp>

#include <imgui.h>

#include <exception>

namespace impasto::app::window {

void PigmentDriftNote::draw(WindowState& state, session::SimWorker& worker) {
  const data::PigmentLibrary& library = data::active_pigment_library();
  worker.with_painting([&](const paintcore::Painting& painting) {
    const Checked now{&painting.pigment_records(), painting.pigment_records().size(), &library};
    if (now == checked_) return;
    checked_ = now;
    dismissed_ = false;
    try {
      drift_ = render::pigments_differing_from_library(painting);
      error_.clear();
    } catch (const std::exception& e) {
      drift_.clear();
      error_ = e.what();
    }
  });
  if (drift_.empty() || dismissed_) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f - 250, 60), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(500, 0));
  ImGui::Begin("Pigments differ from the library", nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped(
      "This painting carries its own copy of each pigment it uses and renders with it. These "
      "differ from the pigment library:");
  std::vector<std::string> replaceable;
  for (const auto& d : drift_) {
    ImGui::BulletText("%s%s", d.name.c_str(),
                      d.missing_from_library ? " (not in the library: kept)" : "");
    if (!d.missing_from_library) replaceable.push_back(d.name);
  }
  ImGui::BeginDisabled(replaceable.empty());
  if (ImGui::Button("Use the library's (re-render)")) {
    try {
      worker.edit_painting([&](paintcore::Painting& painting) {
        render::use_library_pigments(painting, replaceable);
      });
      state.settings_changed = true;  // the palette is rebuilt from the new records
      state.notifications.info("the painting now uses the library's pigments (save to keep them)");
    } catch (const std::exception& e) {
      state.notifications.error(e.what());
    }
    dismissed_ = true;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Keep the painting's")) dismissed_ = true;
  ImGui::End();
}

}  // namespace impasto::app::window
