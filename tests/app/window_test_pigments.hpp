#pragma once
// The pigments the window's model tests paint with, by their names in the pigment database.
#include <string>

namespace impasto::app::window::test {

inline const std::string kWhite = "Titanium White";
inline const std::string kBlue = "Ultramarine Blue";

}  // namespace impasto::app::window::test
