#include "impasto/paintcore/painting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "impasto/paintcore/brush_resample.hpp"
#include "impasto/util/text.hpp"
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
// The subscribers belong to this painting, not to the canvas it holds: they stay, and see the
// new canvas whole.
Painting& Painting::operator=(Painting&& other) noexcept {
  if (this == &other) return *this;
  std::vector<ChangedCells> subscribers;
  if (impl_) subscribers = std::move(impl_->subscribers);
  impl_ = std::move(other.impl_);
  if (impl_) impl_->take_subscribers(std::move(subscribers));
  return *this;
}

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
  if (!std::isfinite(volume_mm3) || volume_mm3 < 0.0 || volume_mm3 > kMaxLoadMm3)
    throw std::runtime_error("load_brush: field 'volume_mm3' must be in [0, " +
                             util::number_text(kMaxLoadMm3) + "], got " +
                             util::number_text(volume_mm3));
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
  {  // the paint must fit on the head before anything changes
    const double area = p.canvas.spec().cell_area_mm2();
    const double height = volume_mm3 / (static_cast<double>(p.brush.covered_cells()) * area);
    const std::size_t cells = p.brush.cell_count();
    float held = 0.0f;  // the fullest cell of the head now
    for (std::size_t c = 0; c < cells; ++c)
      if (p.brush.covers()[c]) held = std::max(held, p.brush.volume_mm()[c]);
    if (held + height > kMaxPaintHeightMm) {
      const double room = std::max(0.0, static_cast<double>(kMaxPaintHeightMm - held)) *
                          static_cast<double>(p.brush.covered_cells()) * area;
      char why[200];
      std::snprintf(why, sizeof why,
                    "load_brush: %g mm³ is more than this head holds: at most %.4g mm³ more "
                    "(%g mm of paint a brush cell)",
                    volume_mm3, room, static_cast<double>(kMaxPaintHeightMm));
      throw std::runtime_error(why);
    }
  }
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
  p.step_from.reset();
  p.clear_pending();
  p.last_move = {0.0, 0.0};
  p.last_move_seconds = 0.0;
  p.stepper.begin_stroke();
}

void Painting::end_stroke() {
  Impl& p = *impl_;
  if (!p.in_stroke) return;
  // The path walked since the last step is stepped too: the stroke ends where the pen did.
  if (p.last_pose && p.step_from &&
      (p.pending_cells > 0.0 || p.pending_seconds > 0.0 || p.pending_depth_mm > 0.0)) {
    BrushPose end = *p.last_pose;
    const auto at = p.step_end({end.x_cells, end.y_cells});
    end.x_cells = at[0];
    end.y_cells = at[1];
    p.arena.execute([&] {
      p.take_step(end, end.x_cells - (*p.step_from)[0], end.y_cells - (*p.step_from)[1],
                  p.pending_seconds, !p.stroke_has_twist);
    });
  }
  if (p.stroke_touched) p.arena.execute([&] { p.lift_brush(); });
  p.step_from.reset();
  p.clear_pending();
  p.in_stroke = false;
  p.last_pose.reset();
  p.pose_before_last.reset();
  p.stepper.finish_stroke(p.brush, slot_count(), p.params);
  if (!p.stroke_touched) {
    p.history.discard();  // nothing changed: nothing to undo
    return;
  }
  // Where the tips last touched the film breaks; then the stroke's paint levels as far as its
  // body lets it (all part of the stroke's undo step).
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

// How far a brush goes on along its travel as it lifts, in head widths at full pressure, and
// how long a brush lifting on the spot takes.
constexpr double kLiftLengthShare = 0.5;
constexpr double kLiftSeconds = 0.1;
constexpr double kMaxLiftSeconds = 0.5;

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
  // A sample that lifts the tip (a mouse's release, where the pressure jumps to 0) ends the
  // stroke where the last pressed sample left the brush, and end_stroke's lift carries it on
  // along its travel as it rises. Stepped to, the pressure fell to nothing over that last
  // segment, a fraction of a millimetre for a mouse, and the brush left on the spot: the
  // trailing edge of its last footprint stayed in the dab as an arc.
  if (!sample.tip_down() && p.last_pose && p.last_pose->depth_mm > 0.0) {
    p.last_time_s = sample.time_s;
    return;
  }
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
    p.step_from.reset();
    p.clear_pending();
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
  // The brush steps at most one cell of travel (CFL), or a big brush's long step
  // (Stepper::max_step_cells), and the squeeze at most max_seconds, counted along the path
  // since the last step: steps fall at the same places whatever the samples' spacing, and a
  // steady stroke's steps are all alike. (A hair over a whole step counts as one: positions
  // come from mm and carry rounding.)
  const double max_seconds = Stepper::max_step_seconds(p.params, p.canvas.cell_mm());
  const double max_cells = Stepper::max_step_cells(p.params, p.brush);
  const double max_depth = Stepper::max_step_depth_mm(p.params, p.brush);
  const double length =
      whole ? curve.length()
            : std::hypot(target.x_cells - from.x_cells, target.y_cells - from.y_cells) * (t1 - t0);
  const double span_seconds = seconds * (t1 - t0);
  const double span_depth = std::abs(target.depth_mm - from.depth_mm) * (t1 - t0);
  if (first || !p.step_from || t0 > 0.0) {
    // A stroke's first sample, or a path coming back within reach: the steps start here.
    p.step_from = p.step_origin = position(0.0);
    p.clear_pending();
  }

  p.arena.execute([&] {
    if (first) p.take_step(target, 0.0, 0.0, 0.0, follows);  // the pen set down
    constexpr double kHair = 1e-9;
    double w = 0.0;  // how far along this segment's simulated part the steps have come
    for (;;) {
      const double to_distance = length > 0.0 ? (max_cells - p.pending_cells) / length
                                              : std::numeric_limits<double>::max();
      const double to_time = span_seconds > 0.0 ? (max_seconds - p.pending_seconds) / span_seconds
                                                : std::numeric_limits<double>::max();
      const double to_depth = span_depth > 0.0 ? (max_depth - p.pending_depth_mm) / span_depth
                                               : std::numeric_limits<double>::max();
      const double next = w + std::max(0.0, std::min({to_distance, to_time, to_depth}));
      if (next > 1.0 + kHair) break;
      const double share = std::min(next, 1.0);
      const double u = whole ? share : t0 + (t1 - t0) * share;
      const std::array<double, 2> here =
          p.step_end(whole ? curve.at(curve.t_at_length_share(share)) : position(share));
      BrushPose pose = lerp(from, target, u);
      pose.x_cells = here[0];
      pose.y_cells = here[1];
      const double step_seconds = p.pending_seconds + span_seconds * (share - w);
      p.take_step(pose, here[0] - (*p.step_from)[0], here[1] - (*p.step_from)[1], step_seconds,
                  follows);
      p.step_from = here;
      p.clear_pending();
      w = share;
      if (share >= 1.0) break;
    }
    p.pending_cells += length * (1.0 - w);
    p.pending_seconds += span_seconds * (1.0 - w);
    p.pending_depth_mm += span_depth * (1.0 - w);
  });
  if (t1 < 1.0) {  // the path leaves the brush's reach: nothing further can touch
    p.step_from.reset();
    p.clear_pending();
  }
  p.pose_before_last = from;
  p.last_pose = target;
}

void Painting::Impl::take_step(BrushPose pose, double move_x, double move_y, double seconds,
                               bool follows, bool lifting) {
  const double moved = std::hypot(move_x, move_y);
  if (follows) {
    // Until the brush has left its first spot by a tenth of its size it faces the way it has
    // gone so far (a first jitter must not set it); then it trails the hand.
    const double follow_cells = std::max(1.0, brush.settings().size_mm / canvas.cell_mm());
    if (!stroke_origin) stroke_origin = {pose.x_cells - move_x, pose.y_cells - move_y};
    const double away_x = pose.x_cells - (*stroke_origin)[0];
    const double away_y = pose.y_cells - (*stroke_origin)[1];
    if (heading_settled && moved > 0.0) {
      heading_rad = follow_heading(*heading_rad, std::atan2(move_y, move_x), moved, follow_cells);
    } else if (!heading_settled && (away_x != 0.0 || away_y != 0.0)) {
      heading_rad = heading_for_travel(std::atan2(away_y, away_x));
      heading_settled = std::hypot(away_x, away_y) >= 0.1 * follow_cells;
    }
    pose.twist_rad = heading_rad.value_or(0.0);
  }
  if (moved >= 0.5) {  // (a step's rounding remainder at the stroke's end says nothing)
    last_move = {move_x, move_y};
    last_move_seconds = seconds;
  }
  const auto before_change = [this](int index) { before_stroke_tile_change(index); };
  if (stepper.step(canvas, brush, static_cast<int>(slots.size()), params, pose, move_x, move_y,
                   seconds, before_change, false, lifting)) {
    stroke_touched = true;
    last_contact = pose;
    ++steps;
    cells_updated += stepper.last_window_cells();
    exchange_medium(canvas, history, brush, stepper, stroke_media);
  }
}

std::array<double, 2> Painting::Impl::step_end(std::array<double, 2> at) const {
  // A long step's end lies a whole number of cells from where the steps started (within half
  // a cell of the path): the head's footprint, sampled between cells, then falls the same way
  // on the cells at every step. Where the ends fell between cells differently from one step
  // to the next, alternate steps pressed differently, and the stroke showed it.
  if (Stepper::max_step_cells(params, brush) <= 1.0 || !step_origin) return at;
  const auto& o = *step_origin;
  return {o[0] + std::round(at[0] - o[0]), o[1] + std::round(at[1] - o[1])};
}

void Painting::Impl::lift_brush() {
  // A brush does not leave all at once: as the hand lifts, it goes on along its travel for a
  // while, pressing less and less, so its heel leaves first and its tips last, and the mark
  // tapers with the bristles' furrows running into its end. Lifted on the spot, the whole
  // footprint split its film at once and left a flat disc with a rim: a stamp. A mouse's
  // release (the pressure jumps to 0) and a pen's ease-off both end this way; a pen that has
  // already eased off has little left to lift. A still brush lifts where it stands.
  if (!last_contact) return;
  const BrushPose start = *last_contact;
  const double max_depth = brush.max_depth_mm();
  const double pressure = max_depth > 0.0 ? std::clamp(start.depth_mm / max_depth, 0.0, 1.0) : 0.0;
  const double travel = std::hypot(last_move[0], last_move[1]);
  const double length =
      travel > 0.0 ? kLiftLengthShare * pressure * brush.settings().size_mm / canvas.cell_mm()
                   : 0.0;
  // The lift takes as long as the stroke's last step went that far, within bounds (a stroke
  // that ended still lifts in kLiftSeconds).
  const double speed = last_move_seconds > 0.0 ? travel / last_move_seconds : 0.0;  // cells/s
  const double lift_seconds =
      length > 0.0 && speed > 0.0 ? std::min(length / speed, kMaxLiftSeconds) : kLiftSeconds;
  // (take_step keeps the last move: the lift's own would turn it.)
  const std::array<double, 2> along =
      travel > 0.0 ? std::array<double, 2>{last_move[0] / travel, last_move[1] / travel}
                   : std::array<double, 2>{0.0, 0.0};
  // The mean paint the brush carries (mm), as far as its tips present it.
  double on_brush = 0.0;
  for (const float height : brush.volume_mm()) on_brush += height;
  const double carried =
      std::min(on_brush / std::max<std::size_t>(brush.covered_cells(), 1), params.tip_film_mm);
  // A quarter of a long step (a cell for heads under about 100 cells), and no more depth a
  // step than the contact's fade allows (Stepper::max_step_depth_mm): the contact shrinks as
  // the tip rises, and a long step holds its contact's outline for its whole length (each
  // step's outline was left as a ring in a dab); a big brush's one-cell steps made its lift
  // cost a frame.
  const double step_cells =
      std::max(1.0, std::floor(0.25 * Stepper::max_step_cells(params, brush)));
  const auto steps = static_cast<int>(std::max(
      {std::ceil(length / step_cells),
       std::ceil(lift_seconds / Stepper::max_step_seconds(params, canvas.cell_mm())),
       std::ceil((start.depth_mm + carried) / Stepper::max_step_depth_mm(params, brush)), 1.0}));
  const double seconds = lift_seconds / static_cast<double>(steps);
  std::array<double, 2> from{start.x_cells, start.y_cells};
  step_origin = from;  // the lift's steps fall on whole cells from its start, as the stroke's
  const bool follows = !stroke_has_twist;
  for (int k = 1; k <= steps; ++k) {
    const double u = static_cast<double>(k) / steps;
    BrushPose pose = start;
    // The tip rises from its last depth to the paint it carries above the surface, where the
    // last of the film between brush and canvas breaks.
    pose.depth_mm = start.depth_mm - (start.depth_mm + carried) * u;
    const auto at =
        step_end({start.x_cells + along[0] * length * u, start.y_cells + along[1] * length * u});
    pose.x_cells = at[0];
    pose.y_cells = at[1];
    take_step(pose, at[0] - from[0], at[1] - from[1], seconds, follows, true);
    from = at;
  }
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
