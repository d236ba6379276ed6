// The Pigment editor and the plot helper, headless: every tab draws for a bundled and a user
// pigment (an ImGui context without a window), the fit tab fits the example measurements,
// and the editor's changes to the user layer can be undone.
#include <gtest/gtest.h>
#include <imgui.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/user_pigment_folder.hpp"
#include "impasto/data/data_dir.hpp"
#include "impasto/data/pigment_library.hpp"
#include "plot_ticks.hpp"
#include "window/pigment_editor.hpp"
#include "window/plot.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

class PigmentEditorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1600, 1000);
    io.DeltaTime = 1.0f / 60;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  void TearDown() override { ImGui::DestroyContext(); }
  void frame(PigmentEditor& editor) {
    ImGui::NewFrame();
    editor.draw(state_, palette_);
    ImGui::Render();
  }
  fs::path user() const { return folder_.user(); }

  impasto::test::UserPigmentFolder folder_{"impasto_pigment_editor"};
  WindowState state_;
  render::SpectralPalette palette_{state_.settings, std::vector<std::string>{}};
};

TEST_F(PigmentEditorTest, EveryTabDrawsAndTheFitMatchesTheExample) {
  PigmentEditor editor;
  editor.open("Red");
  editor.compare_with("Magenta");
  editor.fit_panel().fit((data::data_dir() / "measurements" / "synthetic_mixtures.csv").string());
  for (auto tab :
       {PigmentEditor::Tab::curves, PigmentEditor::Tab::metadata, PigmentEditor::Tab::import,
        PigmentEditor::Tab::fit, PigmentEditor::Tab::compare}) {
    editor.show(tab);
    frame(editor);
    frame(editor);
  }
  // The example is computed from the shipped K and S: the fit gives them back.
  EXPECT_LT(editor.fit_panel().max_delta_e(), 0.01);
  EXPECT_FALSE(std::isnan(editor.fit_panel().max_delta_e()));
  EXPECT_TRUE(editor.is_open());
  EXPECT_TRUE(editor.message().empty()) << editor.message();
}

TEST_F(PigmentEditorTest, AnImportGoesToTheUserLayerAndUndoTakesItBack) {
  std::ifstream in(data::data_dir() / "pigments" / "blue_red_shade.csv");
  std::ofstream out(folder_.dir() / "mine.csv");
  for (std::string line; std::getline(in, line);)
    out << (line.rfind("# name:", 0) == 0 ? "# name: My Blue" : line) << '\n';
  out.close();
  PigmentEditor editor;
  editor.open("Blue Red Shade");
  frame(editor);
  editor.import_file(folder_.dir() / "mine.csv");
  EXPECT_EQ(editor.message(), "imported mine.csv");
  ASSERT_TRUE(fs::exists(user() / "my_blue.csv"));
  EXPECT_EQ(data::active_pigment_library().origin("My Blue")->layer, "user");
  frame(editor);
  editor.import_file(folder_.dir() / "mine.csv");  // a second time: refused, nothing to undo for it
  EXPECT_NE(editor.message().find("exists"), std::string::npos) << editor.message();
  editor.undo();
  EXPECT_FALSE(fs::exists(user() / "my_blue.csv"));
  EXPECT_EQ(data::active_pigment_library().database().find("My Blue"), nullptr);
  frame(editor);
}

TEST(PlotTicks, AreRoundNumbersAndFewEvenForATinyRange) {
  EXPECT_EQ(nice_ticks(360, 750, 5), (std::vector<double>{400, 500, 600, 700}));
  EXPECT_EQ(nice_ticks(0, 1, 4), (std::vector<double>{0, 0.5, 1}));
  EXPECT_LE(nice_ticks(1000.0, std::nextafter(1000.0, 2000.0), 5).size(), 100u);
  EXPECT_TRUE(nice_ticks(1, 1).empty());
}

TEST_F(PigmentEditorTest, APlotReadsItsSeriesBetweenPoints) {
  const PlotSeries s{"s", {400, 500, 600}, {0, 1, 3}};
  EXPECT_EQ(series_at(s, 450), 0.5);
  EXPECT_EQ(series_at(s, 550), 2.0);
  EXPECT_EQ(series_at(s, 300), 0.0);  // held at the ends
  EXPECT_EQ(series_at(s, 700), 3.0);
  ImGui::NewFrame();
  ImGui::Begin("plot");
  PlotOptions o;
  o.markers_x = {450, 550};
  EXPECT_TRUE(std::isnan(draw_plot(o, std::span(&s, 1)))) << "nothing is hovered";
  ImGui::End();
  ImGui::Render();
}

}  // namespace
}  // namespace impasto::app::window
