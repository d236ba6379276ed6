// The Palette's colour target: a recipe becomes the parts sliders' mix (parts of ten, to a
// tenth), and the recipes follow the window's light.
#include <gtest/gtest.h>

#include "impasto/data/pigments.hpp"
#include "window/colour_target.hpp"

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
  WindowState s;
  s.colour_target = {46 / 255.0f, 139 / 255.0f, 87 / 255.0f};  // sea green
  find_recipes(s);
  ASSERT_FALSE(s.recipes.empty());
  EXPECT_EQ(s.recipes_light, s.settings.light);
  EXPECT_LT(s.recipes.back().delta_e00, 3.0);
  const auto daylight = s.recipes.back().srgb;
  s.settings.light = "A";
  find_recipes(s);
  EXPECT_EQ(s.recipes_light, "A");
  EXPECT_NE(s.recipes.back().srgb, daylight) << "the masstone as seen under the new light";
}

}  // namespace
}  // namespace impasto::app::window
