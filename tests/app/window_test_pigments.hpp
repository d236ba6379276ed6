#pragma once
// The pigments the window's model tests paint with, by their names in the pigment database.
#include <string>

namespace impasto::app::window::test {

inline const std::string kWhite = "White";
inline const std::string kBlue = "Blue Red Shade";

}  // namespace impasto::app::window::test
