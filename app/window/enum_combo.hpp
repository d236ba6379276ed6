#pragma once
// A combo box over one of the enum name tables (util::EnumNames): the window offers a choice
// by the same words as the command line and the docs (docs/cli.md).
#include <imgui.h>

#include <string>

#include "impasto/util/enum_names.hpp"

namespace impasto::app::window {

// Returns whether the user chose another value.
template <class Enum, std::size_t N>
bool enum_combo(const char* label, Enum& value, const util::EnumNames<Enum, N>& names) {
  bool changed = false;
  const std::string shown(util::name_of(names, value));
  if (ImGui::BeginCombo(label, shown.c_str())) {
    for (const auto& entry : names) {
      if (ImGui::Selectable(std::string(entry.name).c_str(), entry.value == value) &&
          entry.value != value) {
        value = entry.value;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace impasto::app::window
