// `impasto compare`: a painting against itself is 0 everywhere; one stroke more is found where
// it was painted, in colour and in height, and --max-de00 turns it into a failing status.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "command_line.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("impasto_compare_command_" + std::to_string(getpid()));
    fs::create_directories(dir_);
    paintcore::Painting blank({128, 96, 150.0, 1});
    blank.save(dir_ / "blank.impasto");
    // The same canvas with one stroke across rows 40..56, x from about 30 to 100 cells.
    paintcore::Painting stroke({128, 96, 150.0, 1});
    stroke.set_brush({"round", 2.5, 0.5});
    stroke.load_brush({{"Red Oxide", 1.0}}, 60.0);
    stroke.begin_stroke();
    for (int i = 0; i <= 24; ++i) {
      paintcore::PenSample sample;
      sample.time_s = 0.01 * i;
      sample.x_mm = 5.0 + 0.5 * i;
      sample.y_mm = 8.0;
      sample.pressure = 0.7f;
      sample.buttons = paintcore::kPenTip | paintcore::kPenInRange;
      stroke.stroke_to(sample);
    }
    stroke.end_stroke();
    stroke.save(dir_ / "stroke.impasto");
  }
  void TearDown() override { fs::remove_all(dir_); }

  nlohmann::json compare(const std::string& a, const std::string& b, const std::string& more = "") {
    testing::internal::CaptureStdout();
    run_command_in_process("compare " + (dir_ / a).string() + " " + (dir_ / b).string() +
                           " --json " + more);
    return nlohmann::json::parse(testing::internal::GetCapturedStdout());
  }

  fs::path dir_;
};

TEST_F(CompareCommand, APaintingAgainstItselfIsZero) {
  const nlohmann::json same = compare("stroke.impasto", "stroke.impasto", "--max-de00 0");
  EXPECT_EQ(same["de00_max"].get<double>(), 0.0);
  EXPECT_EQ(same["pixels_over"].get<long>(), 0);
  EXPECT_EQ(same["height_mm_max"].get<double>(), 0.0);
}

TEST_F(CompareCommand, OneStrokeMoreIsFoundWhereItWasPainted) {
  const nlohmann::json found =
      compare("blank.impasto", "stroke.impasto", "-o " + (dir_ / "diff.png").string());
  EXPECT_GT(found["de00_max"].get<double>(), 10.0);
  EXPECT_GT(found["pixels_over"].get<long>(), 200);
  EXPECT_GT(found["height_mm_max"].get<double>(), 0.05);
  // The difference image is dark away from the stroke and bright on it.
  const render::Image diff = render::read_png(dir_ / "diff.png");
  EXPECT_GT(diff.pixel(60, 47)[0], 0.5f);
  EXPECT_LT(diff.pixel(60, 10)[0], 0.05f);
  EXPECT_LT(diff.pixel(120, 90)[0], 0.05f);
  // As a test's one line: a failing status past the allowed difference.
  testing::internal::CaptureStdout();
  EXPECT_THROW(run_command_in_process("compare " + (dir_ / "blank.impasto").string() + " " +
                                      (dir_ / "stroke.impasto").string() + " --max-de00 1"),
               std::runtime_error);
  testing::internal::GetCapturedStdout();
}

TEST_F(CompareCommand, DifferentSizesAreRefusedNamingBoth) {
  paintcore::Painting({64, 48, 150.0, 1}).save(dir_ / "small.impasto");
  try {
    compare("blank.impasto", "small.impasto");
    FAIL() << "two sizes compared";
  } catch (const std::runtime_error& e) {
    testing::internal::GetCapturedStdout();
    EXPECT_NE(std::string(e.what()).find("128x96"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("64x48"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impasto::app
