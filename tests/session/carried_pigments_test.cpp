// Paintings carry their pigments (render/pigment_records.hpp): a painting made with a user
// pigment renders bit-identically after that pigment leaves the library and after its K is
// edited, says which pigments differ from the library, and can take the library's back.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../common/straight_stroke.hpp"
#include "../common/user_pigment_folder.hpp"
#include "impasto/data/data_dir.hpp"
#include "impasto/data/pigment_library.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/pigment_records.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/session/replay.hpp"

namespace impasto::session {
namespace {

namespace fs = std::filesystem;

class CarriedPigments : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(user());
    setenv("XDG_CACHE_HOME", (folder_.dir() / "cache").c_str(), 1);  // carried flake files go there
    write_my_red(1.0);
    data::reload_active_pigment_library();
    render::install_pigment_records();
  }
  void TearDown() override { paintcore::Painting::set_pigment_record_source({}); }
  fs::path user() const { return folder_.user(); }
  // Red's file as "My Red", its K scaled.
  void write_my_red(double k_scale) {
    std::ifstream in(data::data_dir() / "pigments" / "red.csv");
    std::ostringstream out;
    bool header_seen = false;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("# name:", 0) == 0) line = "# name: My Red";
      if (header_seen) {
        const auto c1 = line.find(','), c2 = line.find(',', c1 + 1);
        std::ostringstream row;
        row.precision(17);
        row << line.substr(0, c1) << ',' << std::stod(line.substr(c1 + 1, c2 - c1 - 1)) * k_scale
            << line.substr(c2);
        line = row.str();
      }
      if (line.rfind("wavelength_nm", 0) == 0) header_seen = true;
      out << line << '\n';
    }
    std::ofstream(user() / "my_red.csv") << out.str();
  }

  test::UserPigmentFolder folder_{"impasto_carried_pigments"};
};

paintcore::Painting painted_with(const std::string& pigment) {
  paintcore::Painting p({64, 48, 254.0, 3}, 1);
  p.set_brush(paintcore::BrushSettings{"flat", 3.0, 0.5});
  p.load_brush({{pigment, 1.0}, {"White", 0.2}}, 6.0);
  test::paint_straight_stroke(p, {0.6, 0.2, 2.4, 20, 0.8f, paintcore::kPenTip});
  return p;
}

TEST_F(CarriedPigments, ARenderIsBitIdenticalAfterThePigmentIsRemovedOrEdited) {
  const fs::path file = folder_.dir() / "my_red.impasto";
  painted_with("My Red").save(file);
  render::RenderSettings settings;
  const render::Image before =
      render::render_painting(paintcore::Painting::load(file, 1), settings);

  fs::remove(user() / "my_red.csv");
  data::reload_active_pigment_library();
  ASSERT_EQ(data::PigmentDatabase::defaults().find("My Red"), nullptr);
  const paintcore::Painting orphan = paintcore::Painting::load(file, 1);
  EXPECT_EQ(render::render_painting(orphan, settings).rgb, before.rgb) << "removed";
  const auto missing = render::pigments_differing_from_library(orphan);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_TRUE(missing[0].missing_from_library);

  write_my_red(1.5);
  data::reload_active_pigment_library();
  paintcore::Painting edited = paintcore::Painting::load(file, 1);
  EXPECT_EQ(render::render_painting(edited, settings).rgb, before.rgb) << "K edited";
  const auto drift = render::pigments_differing_from_library(edited);
  ASSERT_EQ(drift.size(), 1u);
  EXPECT_EQ(drift[0].name, "My Red");
  EXPECT_FALSE(drift[0].missing_from_library);

  // Taking the library's version re-renders with the new K: darker and different.
  render::use_library_pigments(edited, {"My Red"});
  EXPECT_TRUE(render::pigments_differing_from_library(edited).empty());
  EXPECT_NE(render::render_painting(edited, settings).rgb, before.rgb);
}

TEST_F(CarriedPigments, ASessionReplaysOntoAPaintingThatCarriesAPigmentTheLibraryLacks) {
  const fs::path file = folder_.dir() / "carrier.impasto";
  painted_with("My Red").save(file);
  fs::remove(user() / "my_red.csv");
  data::reload_active_pigment_library();
  paintcore::Painting painting = paintcore::Painting::load(file, 1);
  const ReplayOptions options;
  SessionPlayer player(painting, options, false);
  input::LoadEvent load;
  load.volume_mm3 = 5.0;
  load.mix = {{"My Red", 1.0}};
  EXPECT_NO_THROW(player.apply(load));
  load.mix = {{"Not A Pigment", 1.0}};
  EXPECT_THROW(player.apply(load), std::runtime_error);
}

TEST_F(CarriedPigments, AFlakePigmentCarriesItsFlakeFiles) {
  const paintcore::Painting p = painted_with("Aluminium Metallic");
  ASSERT_EQ(p.pigment_records().count("Aluminium Metallic"), 1u);
  const auto carried = render::carried_pigments(p);
  const data::Pigment& aluminium = carried->at("Aluminium Metallic");
  ASSERT_FALSE(aluminium.flakes.empty());
  EXPECT_TRUE(fs::is_regular_file(aluminium.flakes));
  EXPECT_TRUE(fs::is_regular_file(aluminium.flakes.parent_path() / "aluminium_rakic1998_ld.csv"));
  EXPECT_EQ(aluminium.K.values,
            data::PigmentDatabase::defaults().get("Aluminium Metallic").K.values);
}

// With HOME and XDG_CACHE_HOME unset (a service, a thumbnailer's sandbox) the flake files a
// painting carries do not go to /tmp/impasto-carried-flakes-UID, where another user may have
// planted a symlink into a folder of this user's: the folder it points at stays untouched.
TEST_F(CarriedPigments, WithNoHomeAPlantedSymlinkInTheTempFolderIsNotFollowed) {
  const paintcore::Painting p = painted_with("Aluminium Metallic");
  const fs::path planted =
      fs::temp_directory_path() / ("impasto-carried-flakes-" + std::to_string(getuid()));
  const fs::path victim = folder_.dir() / "private";
  fs::create_directories(victim);
  std::error_code absent;
  if (fs::symlink_status(planted, absent).type() == fs::file_type::not_found)
    fs::create_directory_symlink(victim, planted);
  const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  unsetenv("HOME");
  unsetenv("XDG_CACHE_HOME");
  const auto carried = render::carried_pigments(p);
  setenv("HOME", home.c_str(), 1);
  setenv("XDG_CACHE_HOME", (folder_.dir() / "cache").c_str(), 1);
  if (fs::is_symlink(planted) && fs::read_symlink(planted) == victim) fs::remove(planted);
  const fs::path flakes = carried->at("Aluminium Metallic").flakes;
  EXPECT_TRUE(fs::is_regular_file(flakes));
  EXPECT_NE(flakes.string().rfind(planted.string(), 0), 0u) << flakes;
  EXPECT_TRUE(fs::is_empty(victim));
}

// A record carries its flake file and that file's table, nothing more: a crafted painting
// cannot make the program write files of its choosing.
TEST_F(CarriedPigments, ARecordCarryingAnUnneededFileIsRefused) {
  const std::string record =
      render::pigment_record(data::PigmentDatabase::defaults().get("Aluminium Metallic")) +
      "#impasto-record-file notes.txt\nanything at all\n";
  try {
    render::pigment_from_record(record, "the painting's pigment 'Aluminium Metallic'");
    ADD_FAILURE() << "the extra file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("carries a file its pigment does not need, 'notes.txt'"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(CarriedPigments, OlderPaintingsWithoutRecordsRenderWithTheLibrary) {
  paintcore::Painting::set_pigment_record_source({});  // as before version 4
  const fs::path file = folder_.dir() / "old.impasto";
  painted_with("My Red").save(file);
  const paintcore::Painting loaded = paintcore::Painting::load(file, 1);
  EXPECT_TRUE(loaded.pigment_records().empty());
  EXPECT_NO_THROW(render::render_painting(loaded, render::RenderSettings{}));
  fs::remove(user() / "my_red.csv");
  data::reload_active_pigment_library();
  EXPECT_THROW(render::render_painting(loaded, render::RenderSettings{}), std::runtime_error);
}

}  // namespace
}  // namespace impasto::session
