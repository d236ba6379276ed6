// Whole paintings to files: PNG and EXR written, PNG read back, bad names rejected.
#include "impasto/render/render_painting.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

using namespace impasto;

namespace {

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impasto_render_test_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

}  // namespace

TEST(RenderPainting, WritesPngOfTheGroundAndExr) {
  paintcore::Painting painting({100, 70, 100.0, 0});
  painting.slot_for("Titanium White");
  render::RenderSettings settings;
  settings.dry_material = {0.0f, 10.0f};

  const auto png = temp_file("ground.png");
  render::render_painting_to_file(painting, settings, png);
  const render::Image read = render::read_png(png);
  ASSERT_EQ(read.width, 100);
  ASSERT_EQ(read.height, 70);
  // Titanium white's R∞ under D65, adapted: a near-white, slightly below 1 in every channel.
  for (float v : read.rgb) {
    ASSERT_GT(v, 0.9f);
    ASSERT_LE(v, 1.0f);
  }

  const auto exr = temp_file("ground.exr");
  render::render_painting_to_file(painting, settings, exr);
  EXPECT_GT(std::filesystem::file_size(exr), 0u);
  std::filesystem::remove(png);
  std::filesystem::remove(exr);
}

TEST(RenderPainting, RejectsUnknownExtensionsAndUnwritablePaths) {
  paintcore::Painting painting({64, 64, 100.0, 0});
  const render::RenderSettings settings;
  EXPECT_THROW(render::render_painting_to_file(painting, settings, temp_file("x.jpg")),
               std::runtime_error);
  EXPECT_THROW(render::render_painting_to_file(painting, settings, "/nonexistent/dir/x.png"),
               std::runtime_error);
  EXPECT_THROW(render::render_painting_to_file(painting, settings, "/nonexistent/dir/x.exr"),
               std::runtime_error);
  EXPECT_THROW(render::read_png(temp_file("missing.png")), std::runtime_error);
}
