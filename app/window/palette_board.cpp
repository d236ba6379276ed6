#include "window/palette_board.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace impasto::app::window {
namespace {

paintcore::CanvasSpec board_spec(double width_mm, double height_mm, double dpi) {
  if (!(width_mm > 0.0) || !(height_mm > 0.0) || !(dpi > 0.0) || !std::isfinite(width_mm) ||
      !std::isfinite(height_mm) || !std::isfinite(dpi)) {
    throw std::runtime_error("palette board: size and dpi must be finite and positive");
  }
  return {static_cast<int>(std::lround(width_mm / paintcore::kMmPerInch * dpi)),
          static_cast<int>(std::lround(height_mm / paintcore::kMmPerInch * dpi)), dpi, 1};
}

}  // namespace

PaletteBoard::PaletteBoard(double width_mm, double height_mm, double dpi)
    : PaletteBoard(paintcore::Painting(board_spec(width_mm, height_mm, dpi), 1)) {}

PaletteBoard::PaletteBoard(paintcore::Painting painting)
    : painting_(std::make_unique<paintcore::Painting>(std::move(painting))),
      changes_(painting_->subscribe_changes()),
      options_(std::make_unique<session::ReplayOptions>()) {
  player_ = std::make_unique<session::SessionPlayer>(*painting_, *options_, false);
}

PaletteBoard PaletteBoard::load(const std::filesystem::path& file) {
  return PaletteBoard(paintcore::Painting::load(file, 1));
}

PaletteBoard::PaletteBoard(PaletteBoard&&) noexcept = default;
PaletteBoard& PaletteBoard::operator=(PaletteBoard&& other) noexcept {
  // The player refers to the painting and options: it goes first, and comes last.
  player_.reset();
  painting_ = std::move(other.painting_);
  changes_ = other.changes_;
  options_ = std::move(other.options_);
  player_ = std::move(other.player_);
  return *this;
}
PaletteBoard::~PaletteBoard() {
  if (player_) player_->finish();
}

std::filesystem::path PaletteBoard::file_beside(const std::filesystem::path& painting) {
  return painting.parent_path() / (painting.stem().string() + ".palette.impasto");
}

void PaletteBoard::save(const std::filesystem::path& file) {
  player_->finish();
  painting_->save(file);
}

double PaletteBoard::width_mm() const {
  return painting_->canvas().width_cells() * painting_->canvas().cell_mm();
}

double PaletteBoard::height_mm() const {
  return painting_->canvas().height_cells() * painting_->canvas().cell_mm();
}

void PaletteBoard::set_brush(const paintcore::BrushSettings& settings) {
  // (No finish() while unchanged: the window calls this every frame, and ending the stroke
  // there cut each scrub into one-frame strokes that lifted off what they had picked up.
  // A changed brush is an event, and apply() ends the stroke before it.)
  const auto& brush = painting_->brush();
  if (!brush.empty() && brush.settings().head == settings.head &&
      brush.settings().size_mm == settings.size_mm &&
      brush.settings().stiffness == settings.stiffness) {
    return;  // unchanged: keep the paint on the brush
  }
  apply(input::BrushEvent{settings.head, settings.size_mm, settings.stiffness, {}});
}

void PaletteBoard::apply(const input::StrokeEvent& event) {
  player_->apply(event);
}

void PaletteBoard::lay_out(const std::vector<input::PigmentPart>& mix, double volume_mm3,
                           double x_mm, double y_mm) {
  if (painting_->brush().empty()) set_brush(paintcore::BrushSettings{});
  player_->finish();
  apply(input::WipeEvent{});
  apply(input::LoadEvent{volume_mm3, mix, {}});
  // A dab: pressed down and circled once over a third of the brush's width.
  const double radius = painting_->brush().settings().size_mm / 6.0;
  constexpr int kSteps = 16;
  for (int i = 0; i <= kSteps; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kSteps;
    paintcore::PenSample sample;
    sample.time_s = 0.01 * i;
    sample.x_mm = x_mm + radius * std::cos(angle);
    sample.y_mm = y_mm + radius * std::sin(angle);
    sample.pressure = 1.0f;
    sample.buttons = paintcore::kPenInRange | (i < kSteps ? paintcore::kPenTip : 0u);
    if (i == kSteps) sample.pressure = 0.0f;
    apply(input::SampleEvent{sample});
  }
  player_->finish();
  apply(input::WipeEvent{});
}

std::optional<input::LoadEvent> PaletteBoard::pick_up() const {
  const paintcore::PaintTotals held = painting_->brush_totals();
  if (!(held.volume > 0.0)) return std::nullopt;
  input::LoadEvent load;
  load.volume_mm3 = held.volume;
  const auto& slots = painting_->pigment_slots();
  for (std::size_t slot = 0; slot < held.pigment.size() && slot < slots.size(); ++slot) {
    if (held.pigment[slot] > 0.0) load.mix.push_back({slots[slot], held.pigment[slot]});
  }
  if (load.mix.empty()) return std::nullopt;
  return load;
}

}  // namespace impasto::app::window
