#pragma once
// Everything that decides how a painting looks, apart from the painting itself.
#include <optional>
#include <string>

#include "impasto/cracks/cavity_model.hpp"
#include "impasto/data/kubelka_munk.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/chromatic_adaptation.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render/spectral_sampling.hpp"
#include "impasto/render/surface_settings.hpp"

namespace impasto::render {

// How the baked reflectance of the dry stack is kept per cell and node.
enum class ReflectanceStorage {
  float32,  // exact
  float16,  // half the memory; rounding below 1e-3 relative (see docs/color-accuracy.md)
};
// Its spellings (--storage), the default first.
inline constexpr util::EnumNames<ReflectanceStorage, 2> kReflectanceStorageNames{
    {{ReflectanceStorage::float32, "float"}, {ReflectanceStorage::float16, "half"}}};

// The flake depth model's spellings (--flake-depth; RenderSettings::flake_masking), the
// default first: with masking and shadowing (Eq. 5 of docs/flakes.md) or without (Eq. 6).
inline constexpr util::EnumNames<bool, 2> kFlakeDepthNames{
    {{true, "masking"}, {false, "no-masking"}}};

// The kind of the main light. Only a light with a direction makes flake sparkles; diffuse
// (overcast) light lights every flake a little and none brightly.
enum class LightType { directional, point, spot, diffuse };
// Its spellings (--light-type), the default first.
inline constexpr util::EnumNames<LightType, 4> kLightTypeNames{
    {{LightType::directional, "directional"},
     {LightType::point, "point"},
     {LightType::spot, "spot"},
     {LightType::diffuse, "diffuse"}}};

// How the far view finds a crack's apparent reflectance (docs/cracks.md): the cracks
// library's choice, Gouffé's closed form or the closed form corrected by the measured tables
// (axial and sky light). Spelled as cracks::kCavityModelNames.
using CrackModel = cracks::CavityModel;

struct RenderSettings {
  // --- light and colour ---
  std::string light = "D65";  // data::light_from_spec: "D65", "A", "F11", "blackbody:5600", file
  // Gaussian nodes 1..16, or 0 for every nm (the reference). 16: the fewest of the optimised
  // rule that hold every kind of paint within 0.3 mean and 1.5 max dE00 of the reference
  // under D65, A and F11 (`impasto bench color`, docs/color-accuracy.md); 8 misses on glazes,
  // stacks and the bare ground, for 20 % less time a relight.
  int wavelengths = 16;
  WavelengthRange range;                              // the measure the nodes are chosen on
  NodeWeights node_weights = NodeWeights::optimised;  // built once a palette (node_cache.hpp)
  ChromaticAdaptation adaptation = ChromaticAdaptation::bradford;
  DisplayEncoding display = DisplayEncoding::srgb;

  // --- paint optics ---
  // Millimetres of paint per unit of K-M optical thickness. The bundled data have S = 1 for
  // White; 0.005 mm makes a 25 um film of white hide 83% of a black ground and
  // 0.1 mm opaque, as real oil and acrylic whites do, while a 1 um glaze stays translucent.
  // See docs/rendering.md.
  double thickness_scale_mm = 0.005;
  // The canvas ground (gesso) reflectance; unset: R∞ of the palette's "White".
  std::optional<data::Spectrum> ground;
  // The paint's surface over its body (Saunderson; km::saunderson): the K-M reflectance as
  // it leaves through the surface, the surface's own reflection left to the specular term.
  // On: the bundled K and S were fitted through this interface, and a flat layer of what a
  // fit was given renders back its measurement (tests/render/measured_paint_test.cpp). Off:
  // the bare K-M reflectance, as before 2026-12-06 (mid-tones some 9 dE00 too light).
  bool saunderson = true;
  double saunderson_k1 = data::kSaundersonK1;  // the paint-air interface's defaults, as
  double saunderson_k2 = data::kSaundersonK2;  // the K/S fit takes them

  // --- shading ---
  double light_azimuth_deg = 225.0;   // from +x (right) toward +y (down the rows): upper left
  double light_elevation_deg = 60.0;  // above the canvas plane
  double ambient = 0.25;              // fraction of the light arriving from everywhere
  shade::Material dry_material{0.04f, 12.0f};
  shade::Material wet_material{0.35f, 80.0f};
  double wet_gloss_mm = 0.02;  // wet paint this thick or more has the full wet gloss

  // --- relief: cast shadows and ambient occlusion (docs/rendering.md) ---
  bool shadows = true;    // off: no march, every cell sees the whole light
  bool occlusion = true;  // off: furrows get the full ambient light
  // The light's apparent diameter for the shadows' penumbra: wider than the bare sun
  // (light_size_deg) so that shadows of 0.1 mm ridges soften over a few cells.
  double shadow_light_diameter_deg = 3.0;
  double shadow_reach_mm = 6.0;      // the march toward the light stops here (cost bound)
  double occlusion_radius_mm = 1.0;  // how far the horizon search looks around a cell

  // --- the light's kind and size: sparkles of flake pigments (docs/flakes.md) ---
  LightType light_type = LightType::directional;
  double light_size_deg = 0.53;       // apparent diameter seen from the canvas (the sun: 0.53)
  double light_distance_mm = 1000.0;  // point, spot: from the canvas centre along light_dir
  double spot_angle_deg = 30.0;       // spot: half-angle of the cone (soft over its outer fifth)
  bool flakes = true;                 // off: flake pigments show their K-M colour only
  bool flake_masking = true;          // depth model with masking/shadowing (Eq. 5) or not (6)

  // --- cracks (docs/cracks.md) ---
  bool cracks = true;  // off: cracked cells show their surface as if uncracked
  CrackModel crack_model = CrackModel::Corrected;

  // --- the surface's reflection and the light spread inside the paint (docs/surface.md) ---
  SurfaceSettings surface;

  // --- storage and threads ---
  ReflectanceStorage storage = ReflectanceStorage::float32;
  int threads = 0;  // 0: TBB's default; results do not depend on it
};

// Throws std::runtime_error naming the first field out of range (NaN included).
void validate(const RenderSettings& settings);

ReflectanceStorage parse_reflectance_storage(std::string_view text);  // kReflectanceStorageNames
LightType parse_light_type(std::string_view text);                    // kLightTypeNames
CrackModel parse_crack_model(std::string_view text);                  // cracks::kCavityModelNames

}  // namespace impasto::render
