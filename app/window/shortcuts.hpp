#pragma once
// The window's keyboard shortcuts: one table that the key handler (paint_window.cpp), the
// menus (their shortcut text) and Help > Shortcuts all read, so a key cannot be documented
// in one place and bound in another.
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace impasto::app::window {

// What a key, a menu item or the window's close button asks for, queued in order on one queue
// (WindowState::commands). The input router carries out most; the File menu the file
// commands (is_file_command), which open its dialogs and prompts.
enum class Command {
  kNew,
  kOpen,
  kSave,
  kSaveAs,
  kExportImage,
  kExportTimelapse,
  kQuit,  // as File > Quit: with unsaved changes, Save / Discard / Cancel
  kUndo,
  kRedo,
  kBrush,         // paint with the brush (leaves the eyedropper; back from the knife)
  kKnife,         // the palette knife head
  kEyedropper,    // pick the paint under the cursor
  kBrushSmaller,  // brush size / kBrushSizeStep
  kBrushLarger,   // brush size * kBrushSizeStep
  kFitCanvas,
  kOneCellPerPixel,
  kShowShortcuts,
};

// Modifier bits, as GLFW numbers them (GLFW_MOD_SHIFT, _CONTROL, _ALT).
inline constexpr int kModShift = 0x1;
inline constexpr int kModCtrl = 0x2;
inline constexpr int kModAlt = 0x4;

struct Shortcut {
  Command command;
  int key;               // GLFW_KEY_*
  int mods;              // exactly these held (Caps Lock, Num Lock and Super are ignored)
  bool repeats = false;  // held down, it acts again (the brush size keys)
};

// What each command is called in menus and in Help > Shortcuts, and its group there.
struct CommandInfo {
  Command command;
  const char* name;
  const char* group;
};

std::span<const Shortcut> shortcuts();
std::span<const CommandInfo> commands();
const CommandInfo& command_info(Command command);

// The command of a key pressed with `mods` (GLFW bits), if any; `repeat`: the key is held
// and the system repeats it.
std::optional<Command> command_for_key(int key, int mods, bool repeat = false);

// "Ctrl+Shift+Z": one chord as the menus show it.
std::string chord_text(const Shortcut& shortcut);
// The first chord of `command`, for a menu item ("" when it has none).
std::string shortcut_text(Command command);
// All chords of `command`, joined by ", " (Help > Shortcuts).
std::string all_shortcut_texts(Command command);

// Mouse gestures, for Help > Shortcuts beside the keys (they are handled by the canvas's
// pointer code, not by this table).
struct GestureHelp {
  const char* gesture;
  const char* what;
};
std::span<const GestureHelp> mouse_gestures();

// Commands waiting to be carried out: a key or a menu item adds one, and whoever carries
// it out takes it.
bool take_command(std::vector<Command>& pending, Command command);
// New, Open, Save, Save as, Export image and Quit: the File menu's own.
bool is_file_command(Command command);
// Takes every file command out of `pending` (the others keep their order) and returns the
// last: pressed twice in one frame, the later wins.
std::optional<Command> take_file_command(std::vector<Command>& pending);

}  // namespace impasto::app::window
