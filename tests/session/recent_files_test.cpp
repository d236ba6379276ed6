// The recent-files list (impasto/session/recent_files.hpp): one name a record whatever bytes the
// name holds (a newline in a file name once split it in two), and older lists still read.
#include "impasto/session/recent_files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace impasto::session {
namespace {

namespace fs = std::filesystem;

class RecentFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("impasto_recent_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    if (const char* old = std::getenv("XDG_CONFIG_HOME")) old_ = old;
    setenv("XDG_CONFIG_HOME", dir_.c_str(), 1);
  }
  void TearDown() override {
    if (old_.empty())
      unsetenv("XDG_CONFIG_HOME");
    else
      setenv("XDG_CONFIG_HOME", old_.c_str(), 1);
    fs::remove_all(dir_);
  }
  fs::path dir_;
  std::string old_;
};

TEST_F(RecentFiles, ANameWithANewlineOrAnEscapeCodeStaysOneRecord) {
  const fs::path odd = dir_ / "two\nlines \x1b[31mred 100% done.impasto";
  const fs::path plain = dir_ / "plain.impasto";
  remember_recent_file(plain);
  remember_recent_file(odd);
  const auto files = load_recent_files();
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0], odd);
  EXPECT_EQ(files[1], plain);
  std::ifstream in(window_config_folder() / "recent.txt");
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 3) << "the header and one line a name";
}

TEST_F(RecentFiles, AnOlderListWithoutTheHeaderReadsAsItWas) {
  fs::create_directories(window_config_folder());
  std::ofstream(window_config_folder() / "recent.txt") << "/a/b%41.impasto\n/c.impasto\n";
  const auto files = load_recent_files();
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0], fs::path("/a/b%41.impasto"));
}

}  // namespace
}  // namespace impasto::session
