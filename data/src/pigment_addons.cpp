// The optional pigment sets Impasto knows of, by name, so a stroke file or a preset that names
// one of their pigments says where it comes from when the set is not installed.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>

#include "impasto/data/pigment_library.hpp"
#include "impasto/util/text.hpp"

namespace impasto::data {
namespace {

// The Golden Matte Fluid Acrylics (Okumura 2005, CC BY-NC-SA 4.0): Impasto's default set
// before the free Kimera set, now the add-on in packaging/pigments-okumura.
constexpr std::array<std::string_view, 27> kOkumuraNames = {"Anthraquinone Blue",
                                                            "Burnt Sienna",
                                                            "Burnt Umber",
                                                            "Carbon Black",
                                                            "Cerulean Blue",
                                                            "Chromium Oxide Green",
                                                            "Cobalt Blue",
                                                            "Diarylide Yellow",
                                                            "Dioxazine Purple",
                                                            "Green Gold",
                                                            "Hansa Yellow Opaque",
                                                            "Jenkins Green",
                                                            "Naphthol Red Medium",
                                                            "Paynes Gray",
                                                            "Permanent Green Light",
                                                            "Phthalo Blue (Green Shade)",
                                                            "Phthalo Green (Blue Shade)",
                                                            "Pyrrole Red",
                                                            "Quinacridone Crimson",
                                                            "Quinacridone Magenta",
                                                            "Raw Sienna",
                                                            "Raw Umber",
                                                            "Red Oxide",
                                                            "Titan Buff",
                                                            "Titanium White",
                                                            "Ultramarine Blue",
                                                            "Yellow Ochre"};

}  // namespace

std::string where_to_get_pigment(std::string_view name) {
  const bool golden =
      std::any_of(kOkumuraNames.begin(), kOkumuraNames.end(),
                  [&](std::string_view known) { return util::equal_ignoring_case(known, name); });
  if (golden) {
    return ": it is one of the Golden acrylics of earlier versions' default set, now an optional "
           "add-on under a non-commercial licence: install the impasto-pigments-okumura "
           "package, or import the files of packaging/pigments-okumura into your user pigment "
           "folder (impasto pigments import FILE.csv), or give --pigments DIR";
  }
  return ": add it to your user pigment folder (impasto pigments import FILE.csv) or give "
         "--pigments DIR";
}

}  // namespace impasto::data
