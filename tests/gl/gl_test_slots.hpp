#pragma once
// The pigment slots the GL tests paint with, each named by what it holds, in slot order.
#include <string>
#include <vector>

namespace impasto::render_gl::test {

inline const std::vector<std::string> kWhitePhthaloRedYellowBlack = {
    "Titanium White", "Phthalo Blue (Green Shade)", "Pyrrole Red", "Hansa Yellow Opaque",
    "Carbon Black"};
inline const std::vector<std::string> kWhitePhthaloRedBlack = {
    "Titanium White", "Phthalo Blue (Green Shade)", "Pyrrole Red", "Carbon Black"};
inline const std::vector<std::string> kWhiteRedBlack = {"Titanium White", "Pyrrole Red",
                                                        "Carbon Black"};
inline const std::vector<std::string> kWhiteRedUltramarine = {"Titanium White", "Pyrrole Red",
                                                              "Ultramarine Blue"};
inline const std::vector<std::string> kWhiteUltramarineSienna = {
    "Titanium White", "Ultramarine Blue", "Burnt Sienna"};
// Two flake paints (data/flakes) among plain pigments.
inline const std::vector<std::string> kWhiteAluminiumUltramarinePearl = {
    "Titanium White", "Aluminium Metallic", "Ultramarine Blue", "Mica Blue Pearl"};

}  // namespace impasto::render_gl::test
