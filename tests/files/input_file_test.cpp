#include "impasto/files/input_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "temp_folder.hpp"

namespace impasto::files {
namespace {

std::string error_of(const std::filesystem::path& path, std::uint64_t limit = kMaxTextFileBytes) {
  try {
    read_whole_file(path, "table", limit);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsAFile) {
  test::TempFolder folder;
  std::ofstream(folder / "a.txt") << "line 1\nline 2\n";
  EXPECT_EQ(read_whole_file(folder / "a.txt", "table"), "line 1\nline 2\n");
  InputFile file(folder / "a.txt", "table", 100);
  std::string line;
  std::getline(file.stream(), line);
  EXPECT_EQ(line, "line 1");
  file.rewind();
  std::getline(file.stream(), line);
  EXPECT_EQ(line, "line 1");
}

TEST(InputFile, RefusesAFolderByName) {
  test::TempFolder folder;
  EXPECT_EQ(error_of(folder.path()),
            folder.path().string() + ": cannot read the table: it is a folder, not a file");
}

TEST(InputFile, RefusesDevicesByName) {
  EXPECT_EQ(error_of("/dev/zero"), "/dev/zero: cannot read the table: it is a device, not a file");
  EXPECT_EQ(error_of("/dev/null"), "/dev/null: cannot read the table: it is a device, not a file");
}

TEST(InputFile, RefusesAPipeWithoutWaitingForAWriter) {
  test::TempFolder folder;
  ASSERT_EQ(::mkfifo((folder / "fifo").c_str(), 0600), 0);
  EXPECT_NE(error_of(folder / "fifo").find("it is a pipe, not a file"), std::string::npos);
}

TEST(InputFile, RefusesAFileOverTheLimitBeforeReadingIt) {
  test::TempFolder folder;
  std::ofstream(folder / "a.txt") << std::string(2000, 'x');
  EXPECT_NE(
      error_of(folder / "a.txt", 1000).find("the table is 2000 bytes, more than the 1000 bytes"),
      std::string::npos);
}

TEST(InputFile, AMissingFileNamesItAndTheReason) {
  EXPECT_EQ(error_of("/nonexistent/x.csv"),
            "/nonexistent/x.csv: cannot open the table (No such file or directory)");
}

}  // namespace
}  // namespace impasto::files
