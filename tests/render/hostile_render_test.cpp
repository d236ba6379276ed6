// The renderer never emits NaN or Inf: every painting of the hostile set (crafted amounts,
// huge declared sizes) and of the fuzz corpus either renders to finite pixels or fails with a
// message naming the field, before allocating what it declares.
#include <gtest/gtest.h>

#include <cmath>

#include "hostile_paintings.hpp"
#include "impasto/render/render_painting.hpp"

namespace impasto {
namespace {

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impasto_hostile_render_" + std::to_string(::getpid()) + "_" + name);
}

// Renders what loads; the count of non-finite channels, or -1 when it does not load.
int non_finite_channels(const std::filesystem::path& file, std::string& error) {
  paintcore::Painting painting = [&] {
    try {
      return paintcore::Painting::load(file, 1);
    } catch (const std::runtime_error& e) {
      error = e.what();
      return paintcore::Painting(paintcore::CanvasSpec{1, 1, 100.0, 0}, 1);
    }
  }();
  if (!error.empty()) return -1;
  render::RenderSettings settings;
  settings.threads = 1;
  try {
    const render::Image image = render::render_painting(painting, settings);
    return static_cast<int>(std::count_if(image.rgb.begin(), image.rgb.end(),
                                          [](float v) { return !std::isfinite(v); }));
  } catch (const std::runtime_error& e) {
    error = e.what();
    return -1;
  }
}

TEST(HostileRender, EveryHostilePaintingRendersFiniteOrFailsByField) {
  for (const auto& hostile : paintcore::test::hostile_paintings()) {
    const auto file = temp_path(hostile.name + ".impasto");
    paintcore::test::write_bytes(file, hostile.bytes);
    std::string error;
    const int bad = non_finite_channels(file, error);
    std::filesystem::remove(file);
    if (hostile.field.empty()) {
      EXPECT_EQ(bad, 0) << hostile.name << ": " << error;
    } else {
      EXPECT_EQ(bad, -1) << hostile.name;
      EXPECT_NE(error.find(hostile.field), std::string::npos) << hostile.name << ": " << error;
    }
  }
}

// A pigment name from a crafted painting reaches the message cut and escaped.
TEST(HostileRender, AnUnknownPigmentNameIsQuotedCutAndEscaped) {
  paintcore::Painting painting(paintcore::CanvasSpec{64, 64, 100.0, 0}, 1);
  painting.slot_for("\x1b[2J" + std::string(3000, 'x'));
  try {
    render::render_painting(painting, render::RenderSettings{});
    FAIL() << "an unknown pigment rendered";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\x1b'), std::string::npos);
    EXPECT_NE(message.find("unknown pigment '\\x1b[2Jxxx"), std::string::npos) << message;
    EXPECT_NE(message.find("(3004 bytes)"), std::string::npos) << message;
  }
}

TEST(HostileRender, EveryPaintingOfTheFuzzCorpusRendersFinite) {
  const std::filesystem::path corpus =
      std::filesystem::path(IMPASTO_SOURCE_DIR) / "tests/fuzz/corpus/paintings";
  int rendered = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    std::string error;
    const int bad = non_finite_channels(entry.path(), error);
    EXPECT_LE(bad, 0) << entry.path();
    if (bad == 0) ++rendered;
  }
  EXPECT_GT(rendered, 0) << "no painting of the corpus loads";
}

}  // namespace
}  // namespace impasto
