#include "impasto/data/pigment_library.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "../common/scratch_folder.hpp"

namespace impasto::data {
namespace {

namespace fs = std::filesystem;

using test::scratch_folder;

void write_pigment(const fs::path& file, const std::string& name, double k) {
  std::ofstream(file) << "# quantity: kubelka_munk\n# name: " << name
                      << "\n# binder: test\nwavelength_nm,K,S\n400," << k << ",1\n700," << k
                      << ",1\n";
}

bool mentions(const std::vector<std::string>& lines, const std::string& a, const std::string& b) {
  for (const auto& line : lines) {
    if (line.find(a) != std::string::npos && line.find(b) != std::string::npos) return true;
  }
  return false;
}

TEST(PigmentLibrary, ABadAndADuplicateFileAreListedAndTheRestLoads) {
  const fs::path dir = scratch_folder("impasto_library_bad");
  write_pigment(dir / "a_red.csv", "Red", 1);
  write_pigment(dir / "b_red_again.csv", "Red", 2);  // duplicate name: skipped
  std::ofstream(dir / "c_broken.csv")
      << "# quantity: kubelka_munk\n# name: Broken\nwavelength_nm,K,S\n400,-1,1\n";
  write_pigment(dir / "d_blue.csv", "Blue", 3);

  const PigmentLibrary library = PigmentLibrary::load({{"test", dir, false, true}});
  ASSERT_EQ(library.database().all().size(), 2u);
  EXPECT_EQ(library.database().get("Red").K.values.front(), 1.0) << "the first file wins";
  EXPECT_EQ(library.database().get("Blue").K.values.front(), 3.0);
  EXPECT_EQ(library.database().find("Broken"), nullptr);
  ASSERT_EQ(library.problems().size(), 2u);
  EXPECT_TRUE(mentions(library.problems(), "b_red_again.csv", "a_red.csv"));
  EXPECT_TRUE(mentions(library.problems(), "b_red_again.csv", "field 'name'"));
  // The CSV error names file, line (4) and column (2: the K cell).
  EXPECT_TRUE(mentions(library.problems(), "c_broken.csv:4:2", "K")) << library.problems()[1];
  fs::remove_all(dir);
}

TEST(PigmentLibrary, ALaterLayerOverridesANameWithANote) {
  const fs::path base = scratch_folder("impasto_library_base");
  const fs::path user = scratch_folder("impasto_library_user");
  write_pigment(base / "red.csv", "Red", 1);
  write_pigment(base / "white.csv", "White", 0.1);
  write_pigment(user / "my_red.csv", "Red", 5);
  write_pigment(user / "green.csv", "Green", 2);

  const PigmentLibrary library = PigmentLibrary::load({{"bundled", base, false, true},
                                                       {"user", user, true, false},
                                                       {"absent", base / "nowhere", false, false}});
  const PigmentDatabase& db = library.database();
  ASSERT_EQ(db.all().size(), 3u);
  EXPECT_EQ(db.get("Red").K.values.front(), 5.0);
  EXPECT_EQ(library.origin("Red")->layer, "user");
  EXPECT_EQ(library.origin("Red")->file, user / "my_red.csv");
  EXPECT_EQ(library.origin("White")->layer, "bundled");
  ASSERT_EQ(library.notes().size(), 1u);
  EXPECT_TRUE(mentions(library.notes(), "my_red.csv", "overrides the bundled"));
  EXPECT_TRUE(library.problems().empty());
  EXPECT_EQ(library.user_folder(), user);
  fs::remove_all(base);
  fs::remove_all(user);
}

TEST(PigmentLibrary, AMissingRequiredFolderOrNoPigmentAtAllIsAnError) {
  const fs::path dir = scratch_folder("impasto_library_empty");
  EXPECT_THROW(PigmentLibrary::load({{"--pigments", dir / "missing", false, true}}),
               std::runtime_error);
  EXPECT_THROW(PigmentLibrary::load({{"--pigments", dir, false, true}}), std::runtime_error);
  fs::remove_all(dir);
}

TEST(PigmentLibrary, TheUserFolderFollowsXdgDataHome) {
  const char* old = std::getenv("XDG_DATA_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_DATA_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(user_pigment_folder(), fs::path("/tmp/xdg-test/impasto/pigments"));
  setenv("XDG_DATA_HOME", "relative/ignored", 1);  // the spec: only absolute paths count
  EXPECT_NE(user_pigment_folder(), fs::path("relative/ignored/impasto/pigments"));
  if (old) {
    setenv("XDG_DATA_HOME", saved.c_str(), 1);
  } else {
    unsetenv("XDG_DATA_HOME");
  }
}

}  // namespace
}  // namespace impasto::data
