#pragma once
// The pigment slots the GL tests paint with, each named by what it holds, in slot order.
#include <string>
#include <vector>

namespace impasto::render_gl::test {

inline const std::vector<std::string> kWhiteBlueRedYellowBlack = {"White", "Blue Green Shade",
                                                                  "Red", "Cold Yellow", "Black"};
inline const std::vector<std::string> kWhiteBlueRedBlack = {"White", "Blue Green Shade", "Red",
                                                            "Black"};
inline const std::vector<std::string> kWhiteRedBlack = {"White", "Red", "Black"};
inline const std::vector<std::string> kWhiteRedBlue = {"White", "Red", "Blue Red Shade"};
inline const std::vector<std::string> kWhiteBlueRedOxide = {"White", "Blue Red Shade", "Red Oxide"};
// Two flake paints (data/flakes) among plain pigments.
inline const std::vector<std::string> kWhiteAluminiumBluePearl = {
    "White", "Aluminium Metallic", "Blue Red Shade", "Mica Blue Pearl"};

}  // namespace impasto::render_gl::test
