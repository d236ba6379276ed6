// The colour target's recipe (colour_recipe.hpp): the inverse finds a mix whose masstone is a
// target made from the palette, a pigment's own masstone is that pigment, and a recipe of more
// pigments is offered only when it comes nearer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/colour_recipe.hpp"

namespace impasto::render {
namespace {

std::size_t index_of(const std::vector<data::Pigment>& palette, const std::string& name) {
  const auto it = std::find_if(palette.begin(), palette.end(),
                               [&](const data::Pigment& p) { return p.name == name; });
  EXPECT_NE(it, palette.end()) << name;
  return static_cast<std::size_t>(it - palette.begin());
}

TEST(ColourRecipe, SrgbTargetsAsLab) {
  const data::Lab white = srgb_to_lab({1.0, 1.0, 1.0});
  EXPECT_NEAR(white.L, 100.0, 0.01);
  EXPECT_NEAR(white.a, 0.0, 0.05);
  EXPECT_NEAR(white.b, 0.0, 0.05);
  // sRGB 119 (0.4663 encoded) is 18.4 % luminance: L* 50.
  EXPECT_NEAR(srgb_to_lab({119 / 255.0, 119 / 255.0, 119 / 255.0}).L, 50.0, 0.1);
  const data::Lab red = srgb_to_lab({1.0, 0.0, 0.0});
  EXPECT_NEAR(red.L, 53.24, 0.05);
  EXPECT_NEAR(red.a, 80.09, 0.1);
  EXPECT_NEAR(red.b, 67.20, 0.1);
}

TEST(ColourRecipe, FindsAMixMadeFromThePalette) {
  const std::vector<data::Pigment>& palette = data::PigmentDatabase::defaults().all();
  const RecipeFinder finder(palette, data::light_from_spec("D65"));
  const std::size_t blue = index_of(palette, "Blue Red Shade");
  const std::size_t white = index_of(palette, "White");
  const Recipe made = finder.evaluate({{blue, 0.15}, {white, 0.85}}, data::Lab{});
  const std::vector<Recipe> recipes = finder.find(made.lab);
  ASSERT_GE(recipes.size(), 2u);
  for (std::size_t k = 0; k < recipes.size(); ++k) EXPECT_EQ(recipes[k].parts.size(), k + 1);
  EXPECT_GT(recipes[0].delta_e00, 5.0) << "one pigment cannot make this tint";
  // The pair is the mix itself.
  const Recipe& two = recipes[1];
  EXPECT_LT(two.delta_e00, 0.3);
  EXPECT_EQ(two.parts[0].pigment, white);
  EXPECT_NEAR(two.parts[0].share, 0.85, 0.03);
  EXPECT_EQ(two.parts[1].pigment, blue);
  // A third pigment only where it comes nearer (here it cannot, by a tenth).
  if (recipes.size() == 3) {
    EXPECT_LT(recipes[2].delta_e00, two.delta_e00 - 0.1);
  }
  double total = 0.0;
  for (const RecipePart& part : two.parts) total += part.share;
  EXPECT_NEAR(total, 1.0, 1e-9);
}

TEST(ColourRecipe, ColoursAreReadAsHexOrDecimal) {
  const std::array<double, 3> hex = parse_srgb_colour("#FF8000");
  EXPECT_EQ(hex[0], 1.0);
  EXPECT_EQ(hex[1], 128 / 255.0);
  EXPECT_EQ(hex[2], 0.0);
  EXPECT_EQ(parse_srgb_colour("ff8000"), hex);
  EXPECT_EQ(parse_srgb_colour("255,128,0"), hex);
  for (const char* bad : {"#ff80", "#gg8000", "1,2", "1,2,256", "1,,3", "-1,2,3", ""})
    EXPECT_THROW(parse_srgb_colour(bad), std::runtime_error) << bad;
}

TEST(ColourRecipe, APigmentsMasstoneIsThatPigment) {
  const std::vector<data::Pigment>& palette = data::PigmentDatabase::defaults().all();
  for (const std::string light : {"D65", "A"}) {
    const RecipeFinder finder(palette, data::light_from_spec(light));
    const std::size_t red = index_of(palette, "Red");
    const Recipe masstone = finder.evaluate({{red, 1.0}}, data::Lab{});
    const std::vector<Recipe> recipes = finder.find(masstone.lab);
    ASSERT_EQ(recipes.size(), 1u) << "no more pigments come nearer than none at all";
    EXPECT_EQ(recipes[0].parts[0].pigment, red) << light;
    EXPECT_LT(recipes[0].delta_e00, 1e-6) << light;
  }
}

}  // namespace
}  // namespace impasto::render
