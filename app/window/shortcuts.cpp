#include "window/shortcuts.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace impasto::app::window {
namespace {

static_assert(kModShift == GLFW_MOD_SHIFT && kModCtrl == GLFW_MOD_CONTROL &&
              kModAlt == GLFW_MOD_ALT);

constexpr std::array kShortcuts{
    Shortcut{Command::kNew, GLFW_KEY_N, kModCtrl},
    Shortcut{Command::kOpen, GLFW_KEY_O, kModCtrl},
    Shortcut{Command::kSave, GLFW_KEY_S, kModCtrl},
    Shortcut{Command::kSaveAs, GLFW_KEY_S, kModCtrl | kModShift},
    Shortcut{Command::kUndo, GLFW_KEY_Z, kModCtrl},
    Shortcut{Command::kRedo, GLFW_KEY_Z, kModCtrl | kModShift},
    Shortcut{Command::kRedo, GLFW_KEY_Y, kModCtrl},
    Shortcut{Command::kBrush, GLFW_KEY_B, 0},
    Shortcut{Command::kKnife, GLFW_KEY_K, 0},
    Shortcut{Command::kEyedropper, GLFW_KEY_I, 0},
    Shortcut{Command::kBrushSmaller, GLFW_KEY_LEFT_BRACKET, 0, true},
    Shortcut{Command::kBrushLarger, GLFW_KEY_RIGHT_BRACKET, 0, true},
    Shortcut{Command::kFitCanvas, GLFW_KEY_F, 0},
    Shortcut{Command::kOneCellPerPixel, GLFW_KEY_1, 0},
    Shortcut{Command::kShowShortcuts, GLFW_KEY_F1, 0},
};

constexpr std::array kCommands{
    CommandInfo{Command::kNew, "New painting", "File"},
    CommandInfo{Command::kOpen, "Open painting", "File"},
    CommandInfo{Command::kSave, "Save", "File"},
    CommandInfo{Command::kSaveAs, "Save as", "File"},
    CommandInfo{Command::kExportImage, "Export image", "File"},
    CommandInfo{Command::kExportTimelapse, "Export time-lapse", "File"},
    CommandInfo{Command::kQuit, "Quit", "File"},
    CommandInfo{Command::kUndo, "Undo", "Edit"},
    CommandInfo{Command::kRedo, "Redo", "Edit"},
    CommandInfo{Command::kBrush, "Brush", "Tools"},
    CommandInfo{Command::kKnife, "Palette knife", "Tools"},
    CommandInfo{Command::kEyedropper, "Eyedropper (pick the paint)", "Tools"},
    CommandInfo{Command::kBrushSmaller, "Smaller brush", "Tools"},
    CommandInfo{Command::kBrushLarger, "Larger brush", "Tools"},
    CommandInfo{Command::kFitCanvas, "Fit canvas", "View"},
    CommandInfo{Command::kOneCellPerPixel, "One cell per pixel", "View"},
    CommandInfo{Command::kShowShortcuts, "Shortcuts", "Help"},
};

constexpr std::array kGestures{
    GestureHelp{"left drag", "paint"},
    GestureHelp{"Alt + left click or drag", "pick the paint (eyedropper), then paint on"},
    GestureHelp{"Space + left drag, middle drag", "pan"},
    GestureHelp{"right drag", "rotate the view"},
    GestureHelp{"wheel", "zoom about the cursor"},
};

std::string key_text(int key) {
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9))
    return std::string(1, static_cast<char>(key));
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  switch (key) {
    case GLFW_KEY_LEFT_BRACKET:
      return "[";
    case GLFW_KEY_RIGHT_BRACKET:
      return "]";
    default:
      return "key " + std::to_string(key);
  }
}

}  // namespace

std::span<const Shortcut> shortcuts() {
  return kShortcuts;
}

std::span<const CommandInfo> commands() {
  return kCommands;
}

const CommandInfo& command_info(Command command) {
  for (const CommandInfo& info : kCommands)
    if (info.command == command) return info;
  throw std::logic_error("shortcuts: a command without a name");
}

std::optional<Command> command_for_key(int key, int mods, bool repeat) {
  const int held = mods & (kModShift | kModCtrl | kModAlt);
  for (const Shortcut& shortcut : kShortcuts)
    if (shortcut.key == key && shortcut.mods == held && (!repeat || shortcut.repeats))
      return shortcut.command;
  return std::nullopt;
}

std::string chord_text(const Shortcut& shortcut) {
  std::string text;
  if (shortcut.mods & kModCtrl) text += "Ctrl+";
  if (shortcut.mods & kModAlt) text += "Alt+";
  if (shortcut.mods & kModShift) text += "Shift+";
  return text + key_text(shortcut.key);
}

std::string shortcut_text(Command command) {
  for (const Shortcut& shortcut : kShortcuts)
    if (shortcut.command == command) return chord_text(shortcut);
  return {};
}

std::string all_shortcut_texts(Command command) {
  std::string text;
  for (const Shortcut& shortcut : kShortcuts) {
    if (shortcut.command != command) continue;
    if (!text.empty()) text += ", ";
    text += chord_text(shortcut);
  }
  return text;
}

std::span<const GestureHelp> mouse_gestures() {
  return kGestures;
}

bool take_command(std::vector<Command>& pending, Command command) {
  const auto found = std::find(pending.begin(), pending.end(), command);
  if (found == pending.end()) return false;
  pending.erase(found);
  return true;
}

bool is_file_command(Command command) {
  switch (command) {
    case Command::kNew:
    case Command::kOpen:
    case Command::kSave:
    case Command::kSaveAs:
    case Command::kExportImage:
    case Command::kExportTimelapse:
    case Command::kQuit:
      return true;
    default:
      return false;
  }
}

std::optional<Command> take_file_command(std::vector<Command>& pending) {
  std::optional<Command> last;
  std::erase_if(pending, [&last](Command command) {
    if (!is_file_command(command)) return false;
    last = command;
    return true;
  });
  return last;
}

}  // namespace impasto::app::window
