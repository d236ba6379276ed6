#pragma once
// The New painting dialog's sizes: a canvas as painters name one (A4, 30 x 40 cm, 16 x 20 in)
// or in any unit (cells, mm, cm, inches), and the cells that makes at a resolution. Pure
// arithmetic, tested without a window (tests/app/canvas_size_choice_test.cpp).
#include <array>
#include <string_view>

namespace impasto::app {

// A standard size, portrait (width <= height); the dialog turns it for landscape.
struct StandardSize {
  std::string_view name;
  double width_mm, height_mm;
};

inline constexpr std::array<StandardSize, 13> kStandardSizes{{
    {"A5", 148, 210},
    {"A4", 210, 297},
    {"A3", 297, 420},
    {"A2", 420, 594},
    {"8 x 10 in", 203.2, 254},
    {"9 x 12 in", 228.6, 304.8},
    {"11 x 14 in", 279.4, 355.6},
    {"12 x 16 in", 304.8, 406.4},
    {"16 x 20 in", 406.4, 508},
    {"18 x 24 in", 457.2, 609.6},
    {"24 x 30 cm", 240, 300},
    {"30 x 40 cm", 300, 400},
    {"50 x 70 cm", 500, 700},
}};

enum class SizeUnit { cells, mm, cm, in };
inline constexpr std::array<std::string_view, 4> kSizeUnitNames{"cells", "mm", "cm", "in"};

// A length in `unit` as millimetres, and back, at `dpi` (cells only need it).
double size_in_mm(double value, SizeUnit unit, double dpi);
double size_from_mm(double mm, SizeUnit unit, double dpi);
// The cells across `mm` at `dpi`, rounded, at least 1.
int cells_across(double mm, double dpi);

}  // namespace impasto::app
