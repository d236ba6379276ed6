#pragma once
// The palette board: a small second painting beside the canvas where the artist lays out
// pigments and mixes them with the brush, as on a real palette. It runs the same simulation
// as the canvas (through session::SessionPlayer, the replay path), so the paint the brush holds
// after mixing is what the brush really picked up; `pick_up` turns that into the load
// that goes onto the canvas brush. The board is saved beside the painting.
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/painting.hpp>

#include <filesystem>
#include <memory>
#include <vector>

#include "impasto/session/replay.hpp"

namespace impasto::app::window {

class PaletteBoard {
 public:
  // A clean board of width_mm x height_mm at `dpi` cells per inch.
  PaletteBoard(double width_mm = 60.0, double height_mm = 40.0, double dpi = 100.0);
  // A board saved before (Painting::save format). Throws std::runtime_error naming the file.
  static PaletteBoard load(const std::filesystem::path& file);
  PaletteBoard(PaletteBoard&&) noexcept;
  PaletteBoard& operator=(PaletteBoard&&) noexcept;
  ~PaletteBoard();

  // Where the board of painting `painting` is kept: `NAME.palette.impasto` beside it.
  static std::filesystem::path file_beside(const std::filesystem::path& painting);
  void save(const std::filesystem::path& file);

  // The board brush takes the canvas brush's head, size and stiffness.
  void set_brush(const paintcore::BrushSettings& settings);
  // Squeezes out a blob of `volume_mm3` of `mix` at (x_mm, y_mm): the board brush is wiped,
  // loaded, pressed down there with a small circling dab, and wiped again, so the board holds
  // what the dab left and the brush is clean afterwards.
  void lay_out(const std::vector<input::PigmentPart>& mix, double volume_mm3, double x_mm,
               double y_mm);
  // A board event (pen sample in board mm, brush, load, wipe), applied at once.
  void apply(const input::StrokeEvent& event);
  // The paint on the board brush as a load for the canvas brush: every pigment it holds,
  // in parts of volume (mm^3), and the volume. nullopt when the brush holds no paint.
  std::optional<input::LoadEvent> pick_up() const;
  // Takes the paint off the board brush (after it was picked up onto the canvas brush).
  void wipe_brush() { apply(input::WipeEvent{}); }

  const paintcore::Painting& painting() const { return *painting_; }
  // The board's tiles changed since the previous take (its panel's image is their one reader).
  std::vector<paintcore::DirtyTile> take_changes() { return painting_->take_changes(changes_); }
  double width_mm() const;
  double height_mm() const;

 private:
  explicit PaletteBoard(paintcore::Painting painting);

  // On the heap so the player's reference survives a move of the board.
  std::unique_ptr<paintcore::Painting> painting_;
  paintcore::Painting::ChangeSubscriber changes_;
  std::unique_ptr<session::ReplayOptions> options_;
  std::unique_ptr<session::SessionPlayer> player_;
};

}  // namespace impasto::app::window
