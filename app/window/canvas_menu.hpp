#pragma once
// The Image menu: Resize canvas..., Crop..., Varnish... and Export at scale and maps... (with
// the relief as a printable solid), each
// with a small dialog. The menu only asks; the window applies a reframe (a new session from
// the changed painting, paint_window.cpp) or a varnish (a session event, recorded as a
// stroke file's `varnish` record) and runs the export (canvas_edit.hpp).
#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "impasto/input/stroke_events.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/canvas_reframe.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/session/canvas_edit.hpp"

namespace impasto::app::window {

// A coat of varnish (Painting::apply_varnish): its finish and thickness over the region's
// cells, or the whole painting; the session event the window submits.
using VarnishRequest = input::VarnishEvent;

// The Varnish dialog's fields as the user left them: `whole`, or the region typed as x, y,
// width and height in cells. Clipped to the canvas when applied (apply_varnish).
VarnishRequest varnish_request(paintcore::Finish finish, float thickness_mm, bool whole,
                               const std::array<int, 4>& region);

// The Export dialog's fields as the user left them.
enum class SolidFormat { kNone, kStl, kPly, kObj };
struct ExportChoice {
  int scale = 2;     // pixels per cell
  std::string stem;  // the files' path less their suffixes
  bool image = true, normal = true;
  int height_format = 1;  // 0 none, 1 16-bit PNG, 2 float EXR
  SolidFormat solid = SolidFormat::kNone;
  render::SolidOptions solid_options;
};
// The files they name (stem, "@2x" beyond scale 1, and each file's suffix), as `impasto
// export` writes them.
session::ExportRequest export_request(const ExportChoice& choice);

struct CanvasMenuRequest {
  std::optional<paintcore::CanvasFrame> frame;    // resize or crop: apply this frame
  std::optional<VarnishRequest> varnish;          // coat the painting
  std::optional<session::ExportRequest> exports;  // write these files
};

class CanvasMenu {
 public:
  // Appends the Image menu to the main menu bar and draws an open dialog. `painting_file`
  // names the exports' default stem.
  CanvasMenuRequest draw(int canvas_width, int canvas_height,
                         const std::optional<std::filesystem::path>& painting_file);

 private:
  enum class Dialog { kNone, kResize, kCrop, kVarnish, kExport };
  CanvasMenuRequest draw_resize();
  CanvasMenuRequest draw_crop();
  CanvasMenuRequest draw_varnish();
  CanvasMenuRequest draw_export();
  // The open dialog (action_dialog, imgui_layout.hpp); it closes when `action` is pressed, on
  // Cancel and by its close box.
  bool dialog(const char* title, const char* action, const std::function<bool()>& body);

  Dialog open_ = Dialog::kNone;
  int canvas_w_ = 0, canvas_h_ = 0;
  int width_ = 0, height_ = 0;
  int anchor_ = 4;             // CanvasAnchor's order: centre
  std::array<int, 4> crop_{};  // x, y, w, h
  paintcore::Finish varnish_finish_ = paintcore::Finish::satin;
  float varnish_mm_ = 0.03f;
  bool varnish_whole_ = true;
  std::array<int, 4> varnish_region_{};  // x, y, w, h
  int scale_index_ = 1;                  // 1x, 2x, 4x
  std::array<char, 512> stem_{};
  ExportChoice export_;
};

}  // namespace impasto::app::window
