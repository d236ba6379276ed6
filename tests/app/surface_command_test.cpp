// `impasto render --surface ...` (app/cli/surface_options.cpp): blinn ignores the finishes and
// renders as the default; ghs changes the image and its finishes differ; the subsurface map
// is written at the canvas's size; bad combinations are refused by name; --gpu renders ghs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "command_line.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

double mean_difference(const render::Image& a, const render::Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(a.rgb[i] - b.rgb[i]);
  return sum / static_cast<double>(a.rgb.size());
}

class SurfaceCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("impasto_surface_command_" + std::to_string(getpid()));
    fs::create_directories(dir_);
    paintcore::Painting({40, 30, 254.0, 5}, 1).save(painting_path());  // a woven bare canvas
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path painting_path() const { return dir_ / "bare.impasto"; }
  fs::path out(const std::string& name) const { return dir_ / name; }

  static void run(const std::string& args) { run_command_in_process(args); }

  render::Image render_with(const std::string& name, const std::string& options) {
    run("render " + painting_path().string() + " --out " + out(name).string() +
        " --light-dir 200,20 " + options);
    return render::read_png(out(name));
  }

  fs::path dir_;
};

TEST_F(SurfaceCommand, BlinnIgnoresFinishesAndGhsChangesTheImage) {
  const render::Image plain = render_with("plain.png", "");
  EXPECT_EQ(render_with("blinn.png", "--surface blinn --medium matte --varnish satin").rgb,
            plain.rgb);
  const render::Image gloss = render_with("gloss.png", "--surface ghs --medium gloss");
  const render::Image matte = render_with("matte.png", "--surface ghs --medium matte");
  EXPECT_NE(gloss.rgb, plain.rgb);
  EXPECT_NE(matte.rgb, gloss.rgb);
  // A gloss varnish over matte paint shows a gloss surface (of the resin's index, a little
  // above the oil's): far nearer the gloss paint than the matte paint it covers.
  const render::Image varnished =
      render_with("varnished.png", "--surface ghs --medium matte --varnish gloss");
  EXPECT_LT(mean_difference(varnished, gloss), 0.3 * mean_difference(matte, gloss));
}

TEST_F(SurfaceCommand, WritesTheSubsurfaceMap) {
  render_with("ghs.png", "--surface ghs --subsurface-map " + out("map.png").string());
  const render::Image map = render::read_png(out("map.png"));
  EXPECT_EQ(map.width, 40);
  EXPECT_EQ(map.height, 30);
  for (float v : map.rgb) EXPECT_EQ(v, 0.0f);  // bare canvas: no layer spreads light
}

TEST_F(SurfaceCommand, RefusesWhatItCannotDo) {
  EXPECT_THROW(render_with("a.png", "--surface phong"), UsageError);
  EXPECT_THROW(render_with("b.png", "--varnish shiny"), UsageError);
  try {
    render_with("c.png", "--subsurface-map " + out("m.png").string());
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--subsurface-map"), std::string::npos) << e.what();
  }
}

#if __has_include(<impasto/render_gl/render_painting_gpu.hpp>)
// --gpu renders the ghs surface with its spread as the CPU does, within a level of 255
// (tests/gl/ghs_surface_test.cpp and subsurface_spread_test.cpp compare the float images;
// here the PNGs round each), and writes the spread's map as the CPU path does.
TEST_F(SurfaceCommand, GpuRendersGhsAsTheCpuDoes) {
  const std::string options = "--surface ghs --medium matte --varnish satin";
  const render::Image gpu =
      render_with("gpu.png", options + " --gpu --subsurface-map " + out("m.png").string());
  EXPECT_EQ(render::read_png(out("m.png")).width, 40);
  const render::Image cpu = render_with("cpu.png", options);
  ASSERT_EQ(gpu.rgb.size(), cpu.rgb.size());
  for (std::size_t i = 0; i < gpu.rgb.size(); ++i) ASSERT_NEAR(gpu.rgb[i], cpu.rgb[i], 1.01 / 255);
  EXPECT_NE(gpu.rgb, render_with("blinn.png", "--gpu").rgb);
}
#endif

}  // namespace
}  // namespace impasto::app
