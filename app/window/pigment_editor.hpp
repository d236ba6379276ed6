#pragma once
// The Pigment editor (menu Pigments > Pigment editor): the layered library as a list with
// colour chips under the window's light, search and each pigment's layer; per pigment its K,
// S, K/S and R∞ curves with the light's wavelength nodes, swatches (masstone, tints 1:1 1:4
// 1:9, glazes over white and black); metadata editing, CSV import, duplicate, rename and
// delete in the user layer with undo and inline validation; the K/S fit from a measurement
// set (pigment_fit_panel.hpp); two pigments compared. Changes go to the user layer's files
// (atomic writes) and the library is read again; paintings keep the pigments they carry.
#include <impasto/data/pigment_library.hpp>
#include <impasto/render/pigment_swatches.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "window/pigment_fit_panel.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class PigmentEditor {
 public:
  // The Pigments menu and, when open, the editor window. `palette` gives the light's nodes.
  void draw(WindowState& state, const render::SpectralPalette& palette);
  bool is_open() const { return open_; }
  void open(const std::string& pigment);
  // For scripts and tests: show a tab at the next draw, compare with a pigment, the fit tab.
  enum class Tab { curves, metadata, import, fit, compare };
  void show(Tab tab) { pending_tab_ = tab; }
  void compare_with(const std::string& pigment) { compare_with_ = pigment; }
  PigmentFitPanel& fit_panel() { return fit_; }
  const std::string& message() const { return message_; }
  // Import into the user layer, as the Import tab's button does; undo the last change.
  void import_file(const std::filesystem::path& file);
  void undo();

 private:
  // The user layer's pigment files as they were before a change.
  struct UndoStep {
    std::string what;
    std::map<std::filesystem::path, std::string> files;
  };
  void list_panel();
  void curves_tab(const data::Pigment& pigment, const std::vector<double>& nodes);
  void metadata_tab(const data::Pigment& pigment, bool in_user_layer);
  void import_tab();
  void compare_tab(const data::Pigment& pigment, const std::vector<double>& nodes);
  // Snapshots the user layer, runs change (which writes files), reloads the library; a
  // failure becomes the message and the snapshot is dropped.
  template <typename F>
  void change(const std::string& what, F&& change);
  const std::vector<render::SwatchColour>& swatches_of(const data::Pigment& pigment);

  bool open_ = false;
  std::optional<Tab> pending_tab_;
  WindowState* state_ = nullptr;
  const data::PigmentLibrary* library_ = nullptr;  // the one the caches below were made for
  std::string light_;                              // and this light
  std::map<std::string, std::vector<render::SwatchColour>> swatches_;
  char search_[64] = {};
  std::string selected_, compare_with_;
  std::string message_;
  bool message_is_error_ = false;
  // Metadata being edited (of `editing_`): name and every key.
  std::string editing_;
  std::array<char, 128> edit_name_{};
  std::vector<std::pair<std::string, std::array<char, 512>>> edit_fields_;
  char new_key_[48] = {};
  char import_path_[512] = {};
  std::string import_check_;
  std::vector<UndoStep> undo_;
  PigmentFitPanel fit_;
};

}  // namespace impasto::app::window
