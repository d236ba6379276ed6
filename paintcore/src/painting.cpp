#include "impasto/paintcore/painting.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "impasto/paintcore/brush_resample.hpp"
#include "levelling.hpp"
#include "painting_impl.hpp"
#include "painting_surface.hpp"

namespace impasto::paintcore {

Painting::Painting(CanvasSpec spec, int threads) : impl_(std::make_unique<Impl>(spec, threads)) {
  if (threads < 0)
    throw std::runtime_error("painting: field 'threads' must be >= 0, got " +
                             std::to_string(threads));
}
Painting::Painting(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Painting::~Painting() = default;
Painting::Painting(Painting&&) noexcept = default;
Painting& Painting::operator=(Painting&&) noexcept = default;

int Painting::threads() const {
  return impl_->threads;
}
const Canvas& Painting::canvas() const {
  return impl_->canvas;
}
const std::vector<std::string>& Painting::pigment_slots() const {
  return impl_->slots;
}
const SimulationParams& Painting::params() const {
  return impl_->params;
}
const Brush& Painting::brush() const {
  return impl_->brush;
}
bool Painting::in_stroke() const {
  return impl_->in_stroke;
}
std::uint64_t Painting::steps() const {
  return impl_->steps;
}
std::uint64_t Painting::cells_updated() const {
  return impl_->cells_updated;
}

int Painting::slot_for(const std::string& pigment) {
  auto& slots = impl_->slots;
  if (pigment.empty()) throw std::runtime_error("pigment mix: field 'pigment' is empty");
  const auto it = std::find(slots.begin(), slots.end(), pigment);
  if (it != slots.end()) return static_cast<int>(it - slots.begin());
  if (slots.size() >= kMaxPigmentSlots)
    throw std::runtime_error("pigment '" + pigment + "': a painting holds at most " +
                             std::to_string(kMaxPigmentSlots) + " pigments");
  slots.push_back(pigment);
  if (const auto& source = pigment_record_source()) {
    for (auto& [name, record] : source(pigment)) impl_->pigment_records.try_emplace(name, record);
  }
  return static_cast<int>(slots.size()) - 1;
}

const std::map<std::string, std::string>& Painting::pigment_records() const {
  return impl_->pigment_records;
}

void Painting::set_pigment_record(const std::string& name, std::string record) {
  impl_->pigment_records[name] = std::move(record);
}

namespace {
Painting::PigmentRecordSource& record_source() {
  static Painting::PigmentRecordSource source;
  return source;
}
}  // namespace

void Painting::set_pigment_record_source(PigmentRecordSource source) {
  record_source() = std::move(source);
}

const Painting::PigmentRecordSource& Painting::pigment_record_source() {
  return record_source();
}

void Painting::set_params(const SimulationParams& params) {
  validate(params);
  impl_->params = params;
}

// --- brush -------------------------------------------------------------------------------

void Painting::set_brush(const BrushSettings& settings) {
  set_brush(settings, default_brushes_dir());
}

void Painting::set_brush(const BrushSettings& settings, const std::filesystem::path& dir) {
  validate(settings);
  set_brush(settings, load_named_brush_head(settings.head, dir));
}

void Painting::set_brush(const BrushSettings& settings, const BrushHead& head) {
  Impl& p = *impl_;
  end_stroke();
  Brush next(head, settings, p.canvas.cell_mm(), slot_count());
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  if (!p.brush.empty()) {
    // The paint stays on the brush, resampled onto the new grid; what float rounding could
    // not keep is booked as wiped, so the ledger and brush_totals() still agree.
    accumulate(p.ledger.wiped,
               resample_brush_paint(p.brush, next, p.canvas.spec().cell_area_mm2()));
  }
  p.brush = std::move(next);
  p.history.commit();
}

void Painting::load_brush(const std::vector<PigmentMixPart>& mix, double volume_mm3, PaintBody body,
                          std::optional<Medium> medium) {
  Impl& p = *impl_;
  if (p.brush.empty()) throw std::runtime_error("load_brush: no brush is set (call set_brush)");
  if (!std::isfinite(volume_mm3) || volume_mm3 < 0.0 || volume_mm3 > 1e9)
    throw std::runtime_error("load_brush: field 'volume_mm3' must be in [0, 1e9], got " +
                             std::to_string(volume_mm3));
  if (mix.empty()) throw std::runtime_error("load_brush: field 'mix' is empty");
  if (medium) validate(*medium);
  double total_parts = 0.0;
  for (const PigmentMixPart& part : mix) {
    if (!std::isfinite(part.parts) || part.parts < 0.0)
      throw std::runtime_error("load_brush: field 'parts' of pigment '" + part.pigment +
                               "' must be finite and >= 0");
    total_parts += part.parts;
  }
  if (!(total_parts > 0.0) || !std::isfinite(total_parts))
    throw std::runtime_error("load_brush: the mix's 'parts' must add up to a positive number");
  std::vector<std::string> new_names;  // slots must suffice before anything changes
  for (const PigmentMixPart& part : mix) {
    if (part.pigment.empty()) throw std::runtime_error("load_brush: field 'pigment' is empty");
    if (std::find(p.slots.begin(), p.slots.end(), part.pigment) == p.slots.end() &&
        std::find(new_names.begin(), new_names.end(), part.pigment) == new_names.end())
      new_names.push_back(part.pigment);
  }
  if (p.slots.size() + new_names.size() > kMaxPigmentSlots)
    throw std::runtime_error("load_brush: the mix needs more than " +
                             std::to_string(kMaxPigmentSlots) + " pigment slots in all");
  end_stroke();
  // Slots allocated here belong to this operation: undo forgets them again.
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  std::vector<double> fraction;
  for (const PigmentMixPart& part : mix) {
    const auto slot = static_cast<std::size_t>(slot_for(part.pigment));
    if (fraction.size() <= slot) fraction.resize(slot + 1, 0.0);
    fraction[slot] += part.parts / total_parts;
  }
  p.brush.ensure_slots(slot_count());
  p.brush.set_body(body);
  const double area = p.canvas.spec().cell_area_mm2();
  const double height = volume_mm3 / (static_cast<double>(p.brush.covered_cells()) * area);
  const std::size_t cells = p.brush.cell_count();
  auto& volume = p.brush.volume_mm();
  auto& pigment = p.brush.pigment_mm();
  PaintTotals added{0.0, std::vector<double>(static_cast<std::size_t>(slot_count()), 0.0)};
  // The ledger counts what each float cell really gained, so ledger and brush agree.
  for (std::size_t c = 0; c < cells; ++c) {
    if (!p.brush.covers()[c]) continue;
    const float before = volume[c];
    volume[c] += static_cast<float>(height);
    added.volume += (static_cast<double>(volume[c]) - before) * area;
    for (std::size_t s = 0; s < fraction.size(); ++s) {
      if (fraction[s] == 0.0) continue;
      float& amount = pigment[s * cells + c];
      const float old = amount;
      amount += static_cast<float>(height * fraction[s]);
      added.pigment[s] += (static_cast<double>(amount) - old) * area;
    }
  }
  mix_brush_medium(p.brush, brush_totals().volume - added.volume, added.volume, medium);
  accumulate(p.ledger.loaded, added);
  p.history.commit();
}

PaintTotals Painting::wipe_brush() {
  Impl& p = *impl_;
  end_stroke();
  const PaintTotals removed = brush_totals();
  const bool nested = p.history.recording();  // inside set_brush
  if (!nested)
    p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(),
                    p.canvas.tile_count());
  std::fill(p.brush.volume_mm().begin(), p.brush.volume_mm().end(), 0.0f);
  std::fill(p.brush.pigment_mm().begin(), p.brush.pigment_mm().end(), 0.0f);
  accumulate(p.ledger.wiped, removed);
  if (!nested) p.history.commit();
  return removed;
}

// --- strokes -----------------------------------------------------------------------------

void Painting::begin_stroke() {
  Impl& p = *impl_;
  end_stroke();
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  p.in_stroke = true;
  p.stroke_touched = false;
  p.last_pose.reset();
  p.pose_before_last.reset();
  p.stroke_has_twist = false;
  p.heading_rad.reset();
  p.heading_settled = false;
  p.stroke_origin.reset();
  p.stroke_tiles.clear();
  p.last_contact.reset();
}

void Painting::end_stroke() {
  Impl& p = *impl_;
  if (!p.in_stroke) return;
  p.in_stroke = false;
  p.last_pose.reset();
  p.pose_before_last.reset();
  p.stepper.finish_stroke(p.brush, slot_count(), p.params);
  if (!p.stroke_touched) {
    p.history.discard();  // nothing changed: nothing to undo
    return;
  }
  // The brush lifts where it last touched, leaving a pile; then the stroke's paint levels as
  // far as its body lets it (both part of the stroke's undo step).
  if (p.last_contact) {
    const auto before_change = [&p](int index) { p.before_stroke_tile_change(index); };
    p.arena.execute([&] {
      if (p.stepper.step(p.canvas, p.brush, slot_count(), p.params, *p.last_contact, 0.0, 0.0, 0.0,
                         before_change, true))
        exchange_medium(p.canvas, p.history, p.brush, p.stepper, p.stroke_media);
    });
    p.last_contact.reset();
  }
  std::sort(p.stroke_tiles.begin(), p.stroke_tiles.end());
  p.stroke_tiles.erase(std::unique(p.stroke_tiles.begin(), p.stroke_tiles.end()),
                       p.stroke_tiles.end());
  std::erase_if(p.stroke_tiles, [&p](int index) { return p.canvas.tile(index) == nullptr; });
  p.arena.execute(
      [&] { settle_wet_paint(p.canvas, p.stroke_tiles, slot_count(), p.brush.body(), p.params); });
  lay_stroke_medium(p.canvas, p.history, p.brush.medium(), p.stroke_tiles, p.stroke_media);
  p.stroke_tiles.clear();
  p.history.commit();
}

namespace {

// A pause between two samples longer than this counts as this long: a still brush has long
// reached its split by then, and a gap in a recording must not cost unbounded steps.
constexpr double kMaxSegmentSeconds = 2.0;

// Clips segment a + t (b - a), t in [0, 1], to the box; returns false when it misses.
bool clip_segment(double ax, double ay, double bx, double by, double lo_x, double lo_y, double hi_x,
                  double hi_y, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double d[2] = {bx - ax, by - ay};
  const double a[2] = {ax, ay};
  const double lo[2] = {lo_x, lo_y};
  const double hi[2] = {hi_x, hi_y};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k];
    double tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

BrushPose lerp(const BrushPose& a, const BrushPose& b, double t) {
  const auto mix = [t](double u, double v) { return u + (v - u) * t; };
  BrushPose pose;
  pose.x_cells = mix(a.x_cells, b.x_cells);
  pose.y_cells = mix(a.y_cells, b.y_cells);
  pose.depth_mm = mix(a.depth_mm, b.depth_mm);
  // The twist turns the short way round.
  pose.twist_rad =
      a.twist_rad + std::remainder(b.twist_rad - a.twist_rad, 2.0 * std::numbers::pi) * t;
  pose.tilt_x_rad = mix(a.tilt_x_rad, b.tilt_x_rad);
  pose.tilt_y_rad = mix(a.tilt_y_rad, b.tilt_y_rad);
  return pose;
}

}  // namespace

void Painting::stroke_to(const PenSample& sample) {
  Impl& p = *impl_;
  validate(sample);  // before anything changes
  if (!p.in_stroke) throw std::runtime_error("stroke_to: no stroke begun (call begin_stroke)");
  if (p.brush.empty()) throw std::runtime_error("stroke_to: no brush is set (call set_brush)");
  BrushPose target = pose_from_sample(sample, p.canvas.cell_mm(), p.brush.max_depth_mm());
  // The mouse and most tablets report no twist: then the head trails the hand.
  p.stroke_has_twist = p.stroke_has_twist || sample.rotation_deg != 0.0f;
  const bool follows = !p.stroke_has_twist;
  const bool first = !p.last_pose.has_value();
  const BrushPose from = p.last_pose.value_or(target);
  const double seconds =
      first ? 0.0 : std::clamp(sample.time_s - p.last_time_s, 0.0, kMaxSegmentSeconds);
  const std::optional<BrushPose> before = p.pose_before_last;
  p.last_time_s = sample.time_s;
  // Only the part of the segment where the brush can reach the canvas is simulated: beyond
  // a margin of two brush widths nothing can touch.
  const double margin = 2.0 * p.brush.cells_across() + 4.0;
  double t0 = 0.0, t1 = 1.0;
  if (!clip_segment(from.x_cells, from.y_cells, target.x_cells, target.y_cells, -margin, -margin,
                    p.canvas.width_cells() + margin, p.canvas.height_cells() + margin, t0, t1)) {
    p.pose_before_last = from;
    p.last_pose = target;
    return;
  }
  // A curve through the samples where the segment lies wholly near the canvas; the clipped
  // straight part of it otherwise (a segment from far away needs no curve).
  const bool whole = t0 == 0.0 && t1 == 1.0;
  std::array<double, 2> before_xy{};
  if (before) before_xy = {before->x_cells, before->y_cells};
  const StrokeSegment curve({from.x_cells, from.y_cells}, {target.x_cells, target.y_cells},
                            whole && before ? &before_xy : nullptr);
  const auto position = [&](double t) {
    if (whole) return curve.at(t);
    const double u = t0 + (t1 - t0) * t;
    return std::array<double, 2>{from.x_cells + (target.x_cells - from.x_cells) * u,
                                 from.y_cells + (target.y_cells - from.y_cells) * u};
  };
  const double cells_per_t =
      whole ? curve.max_speed()
            : std::hypot(target.x_cells - from.x_cells, target.y_cells - from.y_cells) * (t1 - t0);
  // CFL: the brush moves at most one cell per step (by the curve's fastest point: a straight
  // segment is cut into equal whole-cell steps, so a steady stroke leaves no step pattern),
  // or a big brush's long step (Stepper::max_step_cells), and the squeeze at most half a cell.
  // (A hair over a whole step counts as one: positions come from mm and carry rounding.)
  const double max_seconds = Stepper::max_step_seconds(p.params, p.canvas.cell_mm());
  const double max_cells = Stepper::max_step_cells(p.params, p.brush.cells_across());
  const auto count = static_cast<std::int64_t>(
      std::max({1.0, std::ceil(cells_per_t / max_cells - 1e-9), std::ceil(seconds / max_seconds)}));
  const double step_seconds = seconds / static_cast<double>(count);
  const double follow_cells = std::max(1.0, p.brush.settings().size_mm / p.canvas.cell_mm());
  const auto before_change = [&p](int index) { p.before_stroke_tile_change(index); };
  p.arena.execute([&] {
    std::array<double, 2> last = position(0.0);
    for (std::int64_t k = 1; k <= count; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(count);
      const std::array<double, 2> here = position(t);
      const double move_x = here[0] - last[0], move_y = here[1] - last[1];
      last = here;
      BrushPose pose = lerp(from, target, whole ? t : t0 + (t1 - t0) * t);
      pose.x_cells = here[0];
      pose.y_cells = here[1];
      const double moved = std::hypot(move_x, move_y);
      if (follows) {
        // Until the brush has left its first spot by a tenth of its size it faces the way it
        // has gone so far (a first jitter must not set it); then it trails the hand.
        if (!p.stroke_origin) p.stroke_origin = {from.x_cells, from.y_cells};
        const double away_x = here[0] - (*p.stroke_origin)[0];
        const double away_y = here[1] - (*p.stroke_origin)[1];
        if (p.heading_settled && moved > 0.0) {
          p.heading_rad =
              follow_heading(*p.heading_rad, std::atan2(move_y, move_x), moved, follow_cells);
        } else if (!p.heading_settled && (away_x != 0.0 || away_y != 0.0)) {
          p.heading_rad = heading_for_travel(std::atan2(away_y, away_x));
          p.heading_settled = std::hypot(away_x, away_y) >= 0.1 * follow_cells;
        }
        pose.twist_rad = p.heading_rad.value_or(0.0);
      }
      if (p.stepper.step(p.canvas, p.brush, slot_count(), p.params, pose, move_x, move_y,
                         step_seconds, before_change)) {
        p.stroke_touched = true;
        p.last_contact = pose;
        ++p.steps;
        p.cells_updated += p.stepper.last_window_cells();
        exchange_medium(p.canvas, p.history, p.brush, p.stepper, p.stroke_media);
      }
    }
  });
  p.pose_before_last = from;
  p.last_pose = target;
}

// --- drying ------------------------------------------------------------------------------

void Painting::dry(double fraction) {
  Impl& p = *impl_;
  if (!std::isfinite(fraction) || fraction < 0.0 || fraction > 1.0)
    throw std::runtime_error("dry: field 'fraction' must be in [0, 1], got " +
                             std::to_string(fraction));
  end_stroke();
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  const int slots = slot_count();
  const auto f = static_cast<float>(fraction);
  DryLayer layer;
  std::vector<Tile*> wet_tiles;
  for (int index = 0; index < p.canvas.tile_count(); ++index) {
    const Tile* tile = p.canvas.tile(index);
    if (!tile || std::none_of(tile->wet_volume_mm.begin(), tile->wet_volume_mm.end(),
                              [](float v) { return v != 0.0f; }))
      continue;
    p.history.before_tile_change(index, tile);
    p.canvas.mark_dirty(index);
    wet_tiles.push_back(&p.canvas.ensure_tile(index, slots));
    layer.tiles.emplace_back();
    layer.tiles.back().tile_index = index;
  }
  // The bottom fraction of each cell, with the same fraction of every pigment, dries.
  p.arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, wet_tiles.size(), [&](std::size_t k) {
      Tile& tile = *wet_tiles[k];
      DryTile& dry = layer.tiles[k];
      dry.volume_mm.resize(kTileCells);
      for (int c = 0; c < kTileCells; ++c) {
        const float dried = tile.wet_volume_mm[c] * f;
        dry.volume_mm[c] = dried;
        tile.wet_volume_mm[c] -= dried;
        tile.dry_height_mm[c] += dried;
      }
      for (int s = 0; s < slots; ++s) {
        float* wet = tile.pigment(s);
        if (std::none_of(wet, wet + kTileCells, [](float v) { return v != 0.0f; })) continue;
        dry.slots.push_back(static_cast<std::uint8_t>(s));
        const std::size_t offset = dry.pigment_mm.size();
        dry.pigment_mm.resize(offset + kTileCells);
        for (int c = 0; c < kTileCells; ++c) {
          const float dried = wet[c] * f;
          dry.pigment_mm[offset + static_cast<std::size_t>(c)] = dried;
          wet[c] -= dried;
        }
      }
    });
  });
  p.canvas.dry_layers().push_back(std::move(layer));
  dry_varnish(p.canvas, p.history, f);
  p.history.commit();
}

// --- undo --------------------------------------------------------------------------------

bool Painting::undo() {
  end_stroke();
  const CanvasSpec before = impl_->canvas.spec();
  const bool done = impl_->history.undo(impl_->canvas, impl_->brush, impl_->ledger, impl_->slots);
  impl_->forget_weave_cache_if_reframed(before);
  return done;
}

bool Painting::redo() {
  end_stroke();
  const CanvasSpec before = impl_->canvas.spec();
  const bool done = impl_->history.redo(impl_->canvas, impl_->brush, impl_->ledger, impl_->slots);
  impl_->forget_weave_cache_if_reframed(before);
  return done;
}

void Painting::set_undo_budget_bytes(std::size_t bytes) {
  impl_->history.set_budget_bytes(bytes);
}
std::size_t Painting::undo_depth() const {
  return impl_->history.undo_depth();
}
std::size_t Painting::redo_depth() const {
  return impl_->history.redo_depth();
}
std::size_t Painting::undo_bytes() const {
  return impl_->history.bytes();
}

}  // namespace impasto::paintcore
