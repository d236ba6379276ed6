#pragma once
// How the Light panel's direction disc is drawn (panels.cpp), where a screenshot has to find
// it (`impasto bench window --light-drag`): one source for its look.
#include <array>
#include <cstdint>

namespace impasto::app::window {

// The dot on the disc that marks where the light is, and its radius in window pixels.
inline constexpr std::array<std::uint8_t, 3> kLightDotColour = {255, 220, 80};
inline constexpr float kLightDotRadius = 6.0f;

}  // namespace impasto::app::window
