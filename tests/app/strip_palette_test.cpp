// The painter's palette of the strip (strip_palette.hpp): the paints left out read back as
// written, whatever their names hold; a broken line is an error naming its line; a file that
// cannot be read shows every paint and says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../common/scoped_env.hpp"
#include "../common/scratch_folder.hpp"
#include "window/strip_palette.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

TEST(StripPalette, ThePaintsLeftOutReadBackAsWritten) {
  StripPalette palette;
  palette.hidden = {"Aluminium Metallic", "odd\nname %"};
  const StripPalette read = parse_strip_palette(format_strip_palette(palette), "palette.txt");
  EXPECT_EQ(read.hidden, palette.hidden);
  EXPECT_FALSE(read.shows("Aluminium Metallic"));
  EXPECT_TRUE(read.shows("Red"));
  EXPECT_EQ(parse_strip_palette("impasto-palette 1\nhide Red\nhide Red\n", "p").hidden.size(), 1u);
}

TEST(StripPalette, ABrokenLineIsAnErrorNamingIt) {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      parse_strip_palette(text, "palette.txt");
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error_of("palette 1\n"), "palette.txt:1: expected 'impasto-palette 1'");
  EXPECT_EQ(error_of("impasto-palette 1\nshow Red\n"),
            "palette.txt:2: expected 'hide NAME', got 'show Red'");
}

TEST(StripPalette, KeptInTheConfigFolderAndABadFileShowsEveryPaint) {
  const fs::path folder = impasto::test::scratch_folder("impasto_strip_palette");
  const impasto::test::ScopedEnv config("XDG_CONFIG_HOME", folder.string());
  EXPECT_TRUE(load_strip_palette().hidden.empty());
  store_strip_palette({{"Black"}, {}});
  EXPECT_EQ(load_strip_palette().hidden, std::vector<std::string>{"Black"});
  std::ofstream(folder / "impasto" / "palette.txt") << "impasto-palette 1\nkeep Black\n";
  const StripPalette broken = load_strip_palette();
  EXPECT_TRUE(broken.hidden.empty());
  ASSERT_EQ(broken.warnings.size(), 1u);
  EXPECT_NE(broken.warnings[0].find("palette.txt:2: expected 'hide NAME'"), std::string::npos);
  EXPECT_NE(broken.warnings[0].find("every paint shown"), std::string::npos);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace impasto::app::window
