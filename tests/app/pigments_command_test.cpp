// `impasto pigments`: import/export round trips, the user layer's edits, check and fit's
// refusal to overwrite, plot files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../common/user_pigment_folder.hpp"
#include "command_line.hpp"
#include "impasto/data/data_dir.hpp"
#include "impasto/data/pigment_library.hpp"
#include "impasto/data/spectral_csv.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class PigmentsCommand : public ::testing::Test {
 protected:
  // Runs `impasto ARGS` through the registered commands (the library read again first, as a
  // new process would).
  static void run(const std::string& args) {
    data::reload_active_pigment_library();
    run_command_in_process(args);
    data::reload_active_pigment_library();  // what the command changed
  }
  fs::path user() const { return folder_.user(); }

  test::UserPigmentFolder folder_{"impasto_pigments_command"};
};

TEST_F(PigmentsCommand, ImportThenExportLeavesNumbersAndMetadataUnchanged) {
  const fs::path bundled = data::data_dir() / "pigments" / "magenta.csv";
  std::string text = read_text(bundled);
  const std::string name_line = "# name: Magenta";
  text.replace(text.find(name_line), name_line.size(), "# name: My Magenta");
  std::ofstream(folder_.dir() / "mine.csv") << text;
  run("pigments import " + (folder_.dir() / "mine.csv").string());
  ASSERT_TRUE(fs::is_regular_file(user() / "my_magenta.csv"));
  const data::LibraryPigment* origin = data::active_pigment_library().origin("My Magenta");
  ASSERT_NE(origin, nullptr);
  EXPECT_EQ(origin->layer, "user");
  run("pigments export \"My Magenta\" --out " + (folder_.dir() / "back.csv").string());

  const data::SpectralTable in = data::read_spectral_csv(folder_.dir() / "mine.csv");
  const data::SpectralTable out = data::read_spectral_csv(folder_.dir() / "back.csv");
  EXPECT_EQ(in.metadata, out.metadata);
  EXPECT_EQ(in.wavelengths_nm, out.wavelengths_nm);
  ASSERT_EQ(in.columns.size(), out.columns.size());
  for (std::size_t i = 0; i < in.columns.size(); ++i)
    EXPECT_EQ(in.columns[i].values, out.columns[i].values) << in.columns[i].name;
  // And a second round trip is byte for byte the first.
  run("pigments import --force " + (folder_.dir() / "back.csv").string());
  run("pigments export \"My Magenta\" --out " + (folder_.dir() / "again.csv").string());
  EXPECT_EQ(read_text(folder_.dir() / "back.csv"), read_text(folder_.dir() / "again.csv"));
  EXPECT_THROW(run("pigments import " + (folder_.dir() / "back.csv").string()), std::runtime_error)
      << "an existing user pigment is not replaced without --force";
}

TEST_F(PigmentsCommand, AddRenameRemoveTouchOnlyTheUserLayer) {
  run("pigments add \"Warm Red\" --copy-of \"red\" --set binder=oil");
  const data::Pigment& added = data::active_pigment_library().database().get("Warm Red");
  EXPECT_EQ(added.metadata.at("binder"), "oil");
  EXPECT_NE(added.metadata.at("modified").find("copied from Red"), std::string::npos);
  run("pigments rename \"warm red\" \"Hot Red\"");
  EXPECT_FALSE(fs::exists(user() / "warm_red.csv"));
  EXPECT_TRUE(fs::exists(user() / "hot_red.csv"));
  run("pigments remove \"Hot Red\"");
  EXPECT_FALSE(fs::exists(user() / "hot_red.csv"));
  EXPECT_THROW(run("pigments remove \"White\""), std::runtime_error) << "bundled";
  EXPECT_NE(data::active_pigment_library().database().find("White"), nullptr);
}

TEST_F(PigmentsCommand, CheckReportsEveryBadFile) {
  const fs::path folder = folder_.dir() / "check";
  fs::create_directories(folder);
  fs::copy_file(data::data_dir() / "pigments" / "red_oxide.csv", folder / "a.csv");
  fs::copy_file(data::data_dir() / "pigments" / "red_oxide.csv", folder / "b.csv");
  std::ofstream(folder / "c.csv")
      << "# quantity: kubelka_munk\n# name: C\nwavelength_nm,K,S\n400,1,x\n";
  try {
    run("pigments check " + folder.string());
    FAIL() << "a folder with errors passed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("2 files have errors"), std::string::npos) << e.what();
  }
  fs::remove(folder / "b.csv");
  fs::remove(folder / "c.csv");
  EXPECT_NO_THROW(run("pigments check " + folder.string()));
}

TEST_F(PigmentsCommand, FitRefusesToOverwriteAndKeepsMetadata) {
  const std::string fit = "pigments fit " +
                          (data::data_dir() / "measurements" / "synthetic_mixtures.csv").string() +
                          " --out " + (folder_.dir() / "fit").string();
  run(fit);
  const fs::path white = folder_.dir() / "fit" / "white.csv";
  const std::string first = read_text(white);
  EXPECT_NE(first.find("# fitted_from: synthetic_mixtures.csv"), std::string::npos);
  EXPECT_NE(first.find("# licence: CC BY 4.0"), std::string::npos) << "kept from the library";
  EXPECT_THROW(run(fit), std::runtime_error);
  EXPECT_EQ(read_text(white), first);
  std::string edited = first;
  edited.replace(edited.find("# binder: acrylic"), 17, "# binder: oils");
  std::ofstream(white) << edited;
  run(fit + " --force");
  EXPECT_NE(read_text(white).find("# binder: oils"), std::string::npos);
}

TEST_F(PigmentsCommand, PlotWritesSvgAndPng) {
  run("pigments plot \"Blue Red Shade\" --out " + (folder_.dir() / "p.svg").string());
  run("pigments plot \"Blue Red Shade\" --out " + (folder_.dir() / "p.png").string());
  EXPECT_NE(read_text(folder_.dir() / "p.svg").find("Blue Red Shade"), std::string::npos);
  EXPECT_GT(fs::file_size(folder_.dir() / "p.png"), 1000u);
  EXPECT_THROW(run("pigments plot \"Blue Red Shade\" --out " + (folder_.dir() / "p.gif").string()),
               std::runtime_error);
}

}  // namespace
}  // namespace impasto::app
