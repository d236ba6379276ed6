#pragma once
// XYZ (D65-referred, Y = 1 for white) to display RGB through OpenColorIO. Debian's OCIO 2.1
// ships no configs, so the config is built in code from OCIO's built-in transforms.
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/util/enum_names.hpp"

namespace impasto::render {

enum class DisplayEncoding {
  srgb,         // sRGB primaries, piecewise sRGB curve (the default; PNG output)
  display_p3,   // P3 primaries, D65 white, sRGB curve
  rec709,       // Rec.709 primaries, BT.1886 (gamma 2.4)
  rec2020,      // Rec.2020 primaries, BT.1886 (gamma 2.4)
  linear_srgb,  // sRGB/Rec.709 primaries, linear, unclamped (EXR output)
};

// Its spellings (--display), the default first.
inline constexpr util::EnumNames<DisplayEncoding, 5> kDisplayEncodingNames{
    {{DisplayEncoding::srgb, "srgb"},
     {DisplayEncoding::display_p3, "display-p3"},
     {DisplayEncoding::rec709, "rec709"},
     {DisplayEncoding::rec2020, "rec2020"},
     {DisplayEncoding::linear_srgb, "linear-srgb"}}};

// Parses a name of kDisplayEncodingNames; throws std::runtime_error naming the accepted values.
DisplayEncoding parse_display_encoding(std::string_view text);
std::string_view to_string(DisplayEncoding encoding);
// Every encoding, for help texts.
const std::vector<std::string>& display_encoding_names();

// XYZ (D65) to linear sRGB, row-major: what DisplayEncoding::linear_srgb applies.
std::array<double, 9> xyz_to_linear_srgb();
// The sRGB curve (IEC 61966-2-1) of one linear value, clamped to [0, 1] first: for the few
// places that encode a value themselves (swatches, the close-up, benchmarks' 8-bit levels).
double srgb_encoded(double linear);
// The inverse of srgb_encoded: an sRGB-encoded value in [0, 1] → linear.
double srgb_decoded(double encoded);
// The inverse of a row-major 3x3 matrix (by cofactors; the caller's matrix is invertible).
std::array<double, 9> invert_3x3(const std::array<double, 9>& m);

class DisplayTransform {
 public:
  explicit DisplayTransform(DisplayEncoding encoding);
  ~DisplayTransform();
  DisplayTransform(DisplayTransform&&) noexcept;
  DisplayTransform& operator=(DisplayTransform&&) noexcept;

  DisplayEncoding encoding() const { return encoding_; }
  // Converts packed XYZ triples to display RGB in place. Thread-safe.
  void apply(float* xyz_to_rgb, std::size_t pixel_count) const;

 private:
  struct Impl;
  DisplayEncoding encoding_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impasto::render
