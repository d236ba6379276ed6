// Saved mixes (saved_mixes.hpp): the file reads back what was written, whatever the names
// hold; a broken line is an error naming its line; pigments the library lacks are passed over
// with a warning; the file is bounded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../common/scoped_env.hpp"
#include "../common/scratch_folder.hpp"
#include "window/saved_mixes.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kKnown = {"White", "Green", "Cold Yellow", "Red"};

std::string error_of(const std::string& text) {
  try {
    parse_saved_mixes(text, "mixes.txt", kKnown);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SavedMixes, ReadBackAsWrittenWhateverTheNamesHold) {
  const std::vector<SavedMix> mixes = {
      {"Sea green", {{"Green", 4.3f}, {"Cold Yellow", 3.8f}, {"White", 1.9f}}},
      {"50% grey\nsecond line\t%41", {{"White", 1.0f}}},
  };
  const SavedMixes read = parse_saved_mixes(format_saved_mixes(mixes), "mixes.txt", kKnown);
  EXPECT_EQ(read.mixes, mixes);
  EXPECT_TRUE(read.warnings.empty());
}

TEST(SavedMixes, ABrokenLineIsAnErrorNamingIt) {
  EXPECT_EQ(error_of("impasto-mixes 1\npart 1 White\n"), "mixes.txt:2: a part before any mix");
  EXPECT_EQ(error_of("mixes 1\n"), "mixes.txt:1: expected 'impasto-mixes 1'");
  for (const char* parts : {"0", "-1", "nan", "1e9", "abc", "2x"}) {
    EXPECT_EQ(error_of(std::string("impasto-mixes 1\nmix A\npart ") + parts + " White\n"),
              "mixes.txt:3: expected 'part PARTS PIGMENT', PARTS in (0, 1000]")
        << parts;
  }
  EXPECT_EQ(error_of("impasto-mixes 1\nmix A\npart 1\n"),
            "mixes.txt:3: expected 'part PARTS PIGMENT', PARTS in (0, 1000]");
  const std::string other = error_of("impasto-mixes 1\n# a note\n\nrecipe X\n");
  EXPECT_EQ(other, "mixes.txt:4: expected 'mix NAME' or 'part PARTS PIGMENT', got 'recipe X'");
}

TEST(SavedMixes, PigmentsTheLibraryLacksArePassedOverAndSaid) {
  const SavedMixes read = parse_saved_mixes(
      "impasto-mixes 1\nmix A\npart 1 White\npart 2 Cadmium Red\nmix B\npart 3 Ochre\n",
      "mixes.txt", kKnown);
  ASSERT_EQ(read.mixes.size(), 1u);
  EXPECT_EQ(read.mixes[0], (SavedMix{"A", {{"White", 1.0f}}}));
  ASSERT_EQ(read.warnings.size(), 3u);
  EXPECT_NE(read.warnings[0].find("mixes.txt:4: no pigment 'Cadmium Red'"), std::string::npos);
  EXPECT_NE(read.warnings[2].find("mix 'B' has no pigment this library knows"), std::string::npos);
}

TEST(SavedMixes, AtMostSixtyFourAreRead) {
  std::string text = "impasto-mixes 1\n";
  for (int i = 0; i < 70; ++i) text += "mix M" + std::to_string(i) + "\npart 1 Red\n";
  const SavedMixes read = parse_saved_mixes(text, "mixes.txt", kKnown);
  EXPECT_EQ(read.mixes.size(), kMaxSavedMixes);
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("more than 64 mixes"), std::string::npos);
}

TEST(SavedMixes, ThePalettesPartsAndBack) {
  const SavedMix mix = saved_mix("olive", {0.0f, 1.5f, 1.0f, 0.0f}, kKnown);
  EXPECT_EQ(mix, (SavedMix{"olive", {{"Green", 1.5f}, {"Cold Yellow", 1.0f}}}));
  EXPECT_EQ(mix_parts_of(mix, kKnown), (std::vector<float>{0.0f, 1.5f, 1.0f, 0.0f}));
  EXPECT_EQ(mix_description(mix), "1.5 Green + 1 Cold Yellow");
}

TEST(SavedMixes, KeptInTheConfigFolderAndABadFileLosesNothingElse) {
  const fs::path folder = impasto::test::scratch_folder("impasto_saved_mixes");
  const impasto::test::ScopedEnv config("XDG_CONFIG_HOME", folder.string());
  EXPECT_TRUE(load_saved_mixes(kKnown).mixes.empty()) << "no file: no mixes, no warning";
  const std::vector<SavedMix> mixes = {{"A", {{"Red", 2.0f}}}};
  store_saved_mixes(mixes);
  EXPECT_EQ(saved_mixes_path(), folder / "impasto" / "mixes.txt");
  EXPECT_EQ(load_saved_mixes(kKnown).mixes, mixes);
  std::ofstream(saved_mixes_path()) << "impasto-mixes 1\npart 1 Red\n";
  SavedMixes broken = load_saved_mixes(kKnown);
  EXPECT_TRUE(broken.mixes.empty());
  ASSERT_EQ(broken.warnings.size(), 1u);
  EXPECT_NE(broken.warnings[0].find("mixes.txt:2: a part before any mix"), std::string::npos);
  std::ofstream(saved_mixes_path()) << std::string(2 << 20, '#');
  broken = load_saved_mixes(kKnown);
  EXPECT_TRUE(broken.mixes.empty());
  ASSERT_EQ(broken.warnings.size(), 1u);
  EXPECT_NE(broken.warnings[0].find("larger than 1024 kB"), std::string::npos);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace impasto::app::window
