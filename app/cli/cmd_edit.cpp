// impasto edit: the canvas's size — crop to a rectangle, or resize around an anchor — and a
// coat of varnish, saved as a painting whose undo history holds the change (canvas_edit.hpp
// does the work).
#include <impasto/paintcore/canvas_reframe.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/surface_settings.hpp>

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "command.hpp"
#include "impasto/session/canvas_edit.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::edit_cmd {
namespace {

struct EditArgs {
  std::string painting;
  std::string crop;  // X,Y,W,H in cells
  std::optional<CanvasSize> size;
  std::string anchor = "center";
  std::string varnish = "none";
  double varnish_thickness_mm = 0.03;
  std::string region;  // X,Y,W,H in cells
  std::optional<double> dry;
  std::string save;
  double history_mb = 64.0;
};

void run(const EditArgs& args) {
  session::CanvasEdit edit;
  if (!args.crop.empty()) edit.crop = render::parse_cell_region(args.crop, "--crop");
  if (args.size) edit.size = std::pair{args.size->width, args.size->height};
  edit.anchor = paintcore::parse_canvas_anchor(args.anchor);
  edit.varnish = render::parse_varnish(args.varnish);
  edit.varnish_thickness_mm = args.varnish_thickness_mm;
  if (!args.region.empty()) edit.varnish_region = render::parse_cell_region(args.region);
  edit.dry = args.dry;
  if (!edit.crop && !edit.size && !edit.varnish && !edit.varnish_region && !edit.dry)
    throw std::runtime_error(
        "edit: nothing to change (give --crop X,Y,W,H, --size WxH, --varnish FINISH and/or "
        "--dry FRACTION)");
  paintcore::Painting painting = paintcore::Painting::load(args.painting);
  if (!painting.load_warning().empty()) warn(painting.load_warning());
  const session::CanvasEditResult result = edit_canvas(painting, edit);
  painting.set_saved_history_bytes(static_cast<std::size_t>(args.history_mb * (1 << 20)));
  painting.save(args.save);
  std::cout << result.summary(painting) << "\n";
  note("wrote " + args.save);
}

const CommandRegistrar registrar("edit", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand(
      "edit",
      "Crop or resize a painting's canvas, or varnish it (undoable: the saved history holds the "
      "change)");
  auto args = std::make_shared<EditArgs>();
  cmd->add_option("painting", args->painting, "The .impasto painting file")->required();
  cmd->add_option("--crop", args->crop,
                  "Keep the rectangle X,Y,W,H (cells); the paint outside is cut away and reported");
  add_size_option(*cmd, args->size, "the new size (after --crop); new cells are clean canvas");
  cmd->add_option("--anchor", args->anchor,
                  "Where the old canvas sits when --size changes it: center, top-left, top, "
                  "top-right, left, right, bottom-left, bottom, bottom-right")
      ->capture_default_str();
  std::vector<std::string> varnishes{"none"};
  for (const auto& name : util::names_of(render::surface::kFinishNames)) varnishes.push_back(name);
  cmd->add_option("--varnish", args->varnish,
                  "A coat of varnish of this finish over the painting (or --region), wet until "
                  "the painting is dried; ghs renders its surface (docs/surface.md)")
      ->check(CLI::IsMember(varnishes))
      ->capture_default_str();
  cmd->add_option("--varnish-thickness", args->varnish_thickness_mm, "The coat's thickness, mm")
      ->check(finite_range(paintcore::kMinVarnishMm, paintcore::kMaxVarnishMm))
      ->capture_default_str();
  cmd->add_option("--region", args->region,
                  "Varnish only the rectangle X,Y,W,H (cells, after --crop and --size)");
  cmd->add_option("--dry", args->dry,
                  "Last, let the wet paint and varnish dry by this fraction, 0..1 (as a stroke "
                  "file's dry record)")
      ->check(finite_range(0.0, 1.0));
  add_save_option(*cmd, args->save, "the edited painting")->required();
  cmd->add_option("--history-mb", args->history_mb,
                  "Undo history kept in the saved file, newest steps first (0: none)")
      ->check(finite_range(0.0, 1e6))
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::edit_cmd
