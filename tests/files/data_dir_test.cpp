#include "impasto/files/data_dir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "temp_folder.hpp"

namespace impasto::files {
namespace {

namespace fs = std::filesystem;

std::string error_of(const DataDirCandidates& candidates) {
  try {
    find_data_dir(candidates);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// An installed tree: <prefix>/bin/impasto and <prefix>/share/impasto.
struct InstalledTree {
  test::TempFolder prefix;
  InstalledTree() { fs::create_directories(prefix / "share/impasto"); }
  fs::path executable() const { return prefix / "bin/impasto"; }
};

TEST(DataDir, TheEnvironmentVariableComesFirst) {
  test::TempFolder chosen;
  InstalledTree installed;
  test::TempFolder source;
  EXPECT_EQ(find_data_dir({chosen.path().string(), installed.executable(), source.path(),
                           installed.prefix.path()}),
            chosen.path());
}

TEST(DataDir, AnEnvironmentVariableNamingNoFolderIsAnError) {
  InstalledTree installed;
  const std::string missing = (installed.prefix / "missing").string();
  EXPECT_EQ(error_of({missing, installed.executable(), {}, {}}),
            "IMPASTO_DATA_DIR is not a folder: " + missing);
}

TEST(DataDir, TheInstalledTreeBesideTheExecutableComesBeforeTheSourceTree) {
  InstalledTree installed;
  test::TempFolder source;
  EXPECT_EQ(find_data_dir({"", installed.executable(), source.path(), installed.prefix.path()}),
            installed.prefix / "share/impasto");
}

TEST(DataDir, AMovedPrefixIsFoundWhereItNowIs) {
  InstalledTree installed;
  fs::rename(installed.prefix / "share", installed.prefix / "moved");
  fs::create_directories(installed.prefix / "elsewhere/bin");
  fs::rename(installed.prefix / "moved", installed.prefix / "elsewhere/share");
  const fs::path found = find_data_dir({"", installed.prefix / "elsewhere/bin/impasto", {}, {}});
  EXPECT_TRUE(fs::equivalent(found, installed.prefix / "elsewhere/share/impasto"));
}

TEST(DataDir, TheSourceTreeIsTheLastResortOfAProgramInTheBuildFolder) {
  test::TempFolder build;  // an executable in a build tree: no share/impasto beside it
  test::TempFolder source;
  EXPECT_EQ(find_data_dir({"", build / "app/impasto", source.path(), build.path()}), source.path());
}

TEST(DataDir, AnInstalledCopyNeverReadsTheSourceTree) {
  test::TempFolder build;
  test::TempFolder source;
  test::TempFolder elsewhere;  // installed, then its share/impasto removed
  const std::string message =
      error_of({"", elsewhere / "bin/impasto", source.path(), build.path()});
  EXPECT_NE(message.find("no Impasto data folder found"), std::string::npos) << message;
  EXPECT_EQ(message.find(source.path().string()), std::string::npos) << message;
}

TEST(DataDir, NoFolderIsAnErrorThatNamesWhereItLooked) {
  test::TempFolder empty;
  const std::string message = error_of({"", empty / "bin/impasto", empty / "data", empty.path()});
  EXPECT_NE(message.find("no Impasto data folder found"), std::string::npos) << message;
  EXPECT_NE(message.find((empty / "share/impasto").string()), std::string::npos) << message;
  EXPECT_NE(message.find((empty / "data").string()), std::string::npos) << message;
  EXPECT_NE(message.find("set IMPASTO_DATA_DIR"), std::string::npos) << message;
}

TEST(DataDir, ThisBuildFindsItsBundledData) {
  // Under CTest $IMPASTO_DATA_DIR is not set, so this is the lookup a build tree makes.
  EXPECT_TRUE(fs::exists(data_dir() / "brushes" / "round.brush")) << data_dir();
}

}  // namespace
}  // namespace impasto::files
