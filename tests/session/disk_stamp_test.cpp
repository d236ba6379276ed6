// DiskStamp: Save notices a painting file changed on disk since this window read or wrote
// it (another window's save), and not a file touched but unchanged.
#include "impasto/session/disk_stamp.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace impasto::session {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

class DiskStampTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("impasto_disk_stamp_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(DiskStampTest, AnUnchangedFileIsUnchanged) {
  const fs::path file = dir_ / "a.impasto";
  write(file, "painting one");
  const auto stamp = stamp_of(file);
  ASSERT_TRUE(stamp);
  EXPECT_EQ(stamp->size, 12u);
  EXPECT_FALSE(changed_on_disk(file, stamp));
}

TEST_F(DiskStampTest, AnotherSaveIsAChange) {
  const fs::path file = dir_ / "a.impasto";
  write(file, "painting one");
  const auto stamp = stamp_of(file);
  write(file, "painting two, longer");  // another size
  EXPECT_TRUE(changed_on_disk(file, stamp));
  write(file, "painting 1!!");  // the same size, other bytes, a later time
  fs::last_write_time(file, stamp->modified + std::chrono::seconds(2));
  EXPECT_TRUE(changed_on_disk(file, stamp));
}

TEST_F(DiskStampTest, ATouchWithoutNewBytesIsNoChange) {
  const fs::path file = dir_ / "a.impasto";
  write(file, "painting one");
  const auto stamp = stamp_of(file);
  fs::last_write_time(file, stamp->modified + std::chrono::seconds(5));
  EXPECT_FALSE(changed_on_disk(file, stamp));
}

TEST_F(DiskStampTest, AFileThatVanishedOrAppearedIsAChange) {
  const fs::path file = dir_ / "a.impasto";
  EXPECT_FALSE(stamp_of(file));
  EXPECT_FALSE(changed_on_disk(file, std::nullopt)) << "nothing there, nothing known";
  write(file, "new");
  EXPECT_TRUE(changed_on_disk(file, std::nullopt)) << "appeared since";
  const auto stamp = stamp_of(file);
  fs::remove(file);
  EXPECT_TRUE(changed_on_disk(file, stamp)) << "vanished since";
}

}  // namespace
}  // namespace impasto::session
