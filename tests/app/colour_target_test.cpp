// The colour target: a recipe becomes the parts sliders' mix (parts of ten, to a tenth), the
// recipes follow the window's light, and a reference image's pick is its block's mean colour.
#include <gtest/gtest.h>

#include "impasto/data/pigments.hpp"
#include "impasto/render/display.hpp"
#include "window/colour_target.hpp"
#include "window/reference_image.hpp"

namespace impasto::app::window {
namespace {

TEST(ColourTarget, ARecipeBecomesTheMixInPartsOfTen) {
  render::Recipe recipe;
  recipe.parts = {{2, 0.55}, {0, 0.4425}, {4, 0.0075}};
  const std::vector<float> parts = recipe_mix_parts(recipe, 5);
  ASSERT_EQ(parts.size(), 5u);
  EXPECT_FLOAT_EQ(parts[2], 5.5f);
  EXPECT_FLOAT_EQ(parts[0], 4.4f);
  EXPECT_FLOAT_EQ(parts[4], 0.1f) << "every pigment of the recipe keeps a part";
  EXPECT_EQ(parts[1], 0.0f);
  EXPECT_EQ(parts[3], 0.0f);
}

TEST(ColourTarget, TheRecipesAreFoundUnderTheWindowsLight) {
  ColourTarget target;
  target.pick({46 / 255.0f, 139 / 255.0f, 87 / 255.0f}, "D65");  // sea green
  ASSERT_FALSE(target.recipes().empty());
  EXPECT_EQ(target.recipes_light(), "D65");
  EXPECT_LT(target.recipes().back().delta_e00, 3.0);
  const auto daylight = target.recipes().back().srgb;
  target.pick(target.target(), "A");
  EXPECT_EQ(target.recipes_light(), "A");
  EXPECT_NE(target.recipes().back().srgb, daylight) << "the masstone as seen under the new light";
}

TEST(ReferenceImage, APickIsTheMeanOfItsBlockInLinearLight) {
  // 4 x 3 pixels: black and white columns in turn, one red pixel at (3, 2).
  ReferencePixels pixels{4, 3, std::vector<std::uint8_t>(36, 0)};
  for (int y = 0; y < 3; ++y)
    for (int x = 1; x < 4; x += 2)
      for (int c = 0; c < 3; ++c) pixels.rgb[static_cast<std::size_t>(3 * (4 * y + x) + c)] = 255;
  pixels.rgb[3 * (4 * 2 + 3) + 1] = 0;
  pixels.rgb[3 * (4 * 2 + 3) + 2] = 0;
  // Inside: 6 of 9 pixels white, so two thirds of the light, encoded (not 170/255).
  const std::array<float, 3> middle = picked_colour(pixels, 2, 1);
  EXPECT_NEAR(middle[0], render::srgb_encoded(6.0 / 9.0), 1e-6);
  // At the corner: the 4 pixels inside the image; one of them is red.
  const std::array<float, 3> corner = picked_colour(pixels, 3, 2);
  EXPECT_NEAR(corner[0], render::srgb_encoded(2.0 / 4.0), 1e-6);
  EXPECT_NEAR(corner[1], render::srgb_encoded(1.0 / 4.0), 1e-6);
}

}  // namespace
}  // namespace impasto::app::window
