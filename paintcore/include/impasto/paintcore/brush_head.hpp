#pragma once
// Brush head shapes, read from data files (one head per file, e.g. brushes/round.brush).
// A head is a perturbation-function shape over the unit square of brush space (u, v in
// [-1, 1], scaled by half the brush size): a base quadric plus cubed perturbation quadrics,
//   F'(u, v) = F(u, v) + sum_i f_i * max(Q_i(u, v), 0)^3.
// The head covers the cells where F' > 0; its underside rises above the tip by
//   rise * (1 - min(F', 1))   (in half brush sizes),
// so where F' >= 1 the head is flat and touches first. The format is in docs/brushes.md.
#include <array>
#include <cstdio>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::paintcore {

// q(u, v) = uu*u^2 + vv*v^2 + uv*u*v + u_lin*u + v_lin*v + constant
struct Quadric2 {
  double uu = 0, vv = 0, uv = 0, u_lin = 0, v_lin = 0, constant = 0;
  double operator()(double u, double v) const {
    return uu * u * u + vv * v * v + uv * u * v + u_lin * u + v_lin * v + constant;
  }
};

struct Perturbation {
  double factor = 0;  // f_i, the form factor
  Quadric2 shape;     // Q_i
};

// The bristles at the head's underside: tips in columns across u, each running along v
// (the direction the head is drawn in), so they plough furrows along the stroke.
struct Bristles {
  double spacing_mm = 0;  // distance between bristle columns; 0: a smooth head (no bristles)
  double depth_mm = 0;    // how far a gap between bristles rises above their tips
  double jitter = 0;      // spread of the bristles' lengths, as a share of depth_mm (0..1)
  bool operator==(const Bristles&) const = default;
};

struct BrushHead {
  std::string name;
  std::string description;
  double rise = 0.5;  // rise of the underside where F' reaches 0, in half brush sizes
  Quadric2 base;
  std::vector<Perturbation> perturbations;
  Bristles bristles;
  double splay = 0;  // under full pressure the footprint widens by this share (0..1)

  double field(double u, double v) const;  // F'(u, v)
  bool covers(double u, double v) const { return field(u, v) > 0.0; }
  // Height of the underside above the tip at (u, v), in half brush sizes.
  double height(double u, double v) const;
  // Height (mm) the bristles add at u_mm across the head (0 at a bristle's tip).
  double bristle_height_mm(double u_mm) const;
  // Which column of bristles lies at u_mm across the head (column 0 at the centre line).
  long bristle_column(double u_mm) const;
};

inline constexpr int kMaxPerturbations = 64;

// The head's bristle settings, each with its one range: a head file (`bristles SPACING DEPTH
// JITTER`, `splay X`), a stroke file's brush record (`bristle_spacing=MM` ...) and a painting
// are checked against this table.
struct BristleSetting {
  std::string_view key;   // its name in a stroke file's brush record
  std::string_view unit;  // "mm", or empty for a share
  double min, max;
  double& (*of)(BrushHead&);
  bool holds(double value) const { return value >= min && value <= max; }  // NaN fails
  std::string range_text() const {                                         // "0..100 mm"
    char text[64];
    std::snprintf(text, sizeof text, "%g..%g%s%.*s", min, max, unit.empty() ? "" : " ",
                  static_cast<int>(unit.size()), unit.data());
    return text;
  }
};
inline constexpr std::array<BristleSetting, 4> kBristleSettings{{
    {"bristle_spacing", "mm", 0.0, 100.0,
     [](BrushHead& h) -> double& { return h.bristles.spacing_mm; }},
    {"bristle_depth", "mm", 0.0, 100.0,
     [](BrushHead& h) -> double& { return h.bristles.depth_mm; }},
    {"bristle_jitter", "", 0.0, 1.0, [](BrushHead& h) -> double& { return h.bristles.jitter; }},
    {"splay", "", 0.0, 1.0, [](BrushHead& h) -> double& { return h.splay; }},
}};
// The setting named `key`, or nullptr. (Inline: the stroke reader checks brush records with
// it without linking the engine.)
inline const BristleSetting* find_bristle_setting(std::string_view key) {
  for (const BristleSetting& setting : kBristleSettings)
    if (setting.key == key) return &setting;
  return nullptr;
}
// "bristle_spacing, bristle_depth, bristle_jitter, splay", for messages.
inline std::string bristle_setting_names() {
  std::string names;
  for (const BristleSetting& setting : kBristleSettings)
    names += (names.empty() ? "" : ", ") + std::string(setting.key);
  return names;
}

// Parses a head file's text; errors name `source` and the line ("round.brush:4: ...").
BrushHead parse_brush_head(std::istream& in, const std::string& source);
// Reads and parses one file; throws std::runtime_error naming the file when it can't.
BrushHead load_brush_head(const std::filesystem::path& file);

// The brushes folder: $IMPASTO_DATA_DIR/brushes when that variable is set, else the source
// tree's data/brushes.
std::filesystem::path default_brushes_dir();
// Loads head `name` (letters, digits, '_' and '-' only) from `dir`/<name>.brush.
BrushHead load_named_brush_head(const std::string& name,
                                const std::filesystem::path& dir = default_brushes_dir());

}  // namespace impasto::paintcore
