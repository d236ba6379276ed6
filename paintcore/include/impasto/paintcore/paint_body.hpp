#pragma once
// A paint's body: how stiff it is, from fluid acrylic to knife paste. Paints are viscoplastic
// (Bingham): below their yield stress they hold their shape, above it they flow. A ridge of
// paint h mm thick on a slope s loads its base with rho g h s; where that stays below the
// yield stress the ridge stands (docs/simulation.md, "Paint body").
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace impasto::paintcore {

enum class PaintBody : std::uint8_t { fluid, soft, heavy, paste };

struct PaintBodyInfo {
  PaintBody body;
  std::string_view name;
  double yield_stress_pa;  // below it the paint does not flow
  double viscosity_pa_s;   // plastic viscosity above it
};

// Orders of magnitude for artists' paints (notes/thick-paint.md): fluid acrylics and glazing
// media near zero, soft-body paint ~10 Pa, heavy-body acrylics and oils 10-100 Pa, knife
// pastes and impasto gels several hundred.
inline constexpr std::array<PaintBodyInfo, 4> kPaintBodies{{
    {PaintBody::fluid, "fluid", 0.5, 0.5},
    {PaintBody::soft, "soft", 10.0, 5.0},
    {PaintBody::heavy, "heavy", 60.0, 30.0},
    {PaintBody::paste, "paste", 400.0, 200.0},
}};

inline constexpr PaintBody kDefaultPaintBody = PaintBody::heavy;

// Weight per volume of paint (rho g, rho ~ 1.5 g/cm^3), in Pa per mm of height.
inline constexpr double kPaintWeightPaPerMm = 1500.0 * 9.81 * 1e-3;

inline const PaintBodyInfo& body_info(PaintBody body) {
  return kPaintBodies[static_cast<std::size_t>(body)];
}
// (Inline: the input module reads body names in stroke files with paintcore's headers only.)
inline std::optional<PaintBody> paint_body_from_name(std::string_view name) {
  for (const PaintBodyInfo& info : kPaintBodies)
    if (info.name == name) return info.body;
  return std::nullopt;
}
// "fluid, soft, heavy, paste": for error messages and help texts.
inline std::string paint_body_names() {
  std::string names;
  for (const PaintBodyInfo& info : kPaintBodies) {
    if (!names.empty()) names += ", ";
    names += info.name;
  }
  return names;
}

}  // namespace impasto::paintcore
