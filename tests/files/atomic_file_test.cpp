#include "impasto/files/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "temp_folder.hpp"

namespace impasto::files {
namespace {

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void put(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Names in the folder other than the ones given: a temp file left behind shows up here.
std::vector<std::string> others(const std::filesystem::path& folder,
                                const std::vector<std::string>& known) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (std::find(known.begin(), known.end(), name) == known.end()) out.push_back(name);
  }
  return out;
}

mode_t mode_of(const std::filesystem::path& file) {
  struct stat st {};
  EXPECT_EQ(::stat(file.c_str(), &st), 0);
  return st.st_mode & 07777;
}

TEST(AtomicFile, WritesANewFileAndLeavesNoTemp) {
  test::TempFolder folder;
  write_file_atomically(folder / "a.txt", "hello");
  EXPECT_EQ(contents(folder / "a.txt"), "hello");
  EXPECT_TRUE(others(folder.path(), {"a.txt"}).empty());
}

// A name up to the file system's 255 bytes saves, multi-byte characters included (73 CJK
// characters, 219 bytes, once failed: the temp name beside it was longer than a name may be).
TEST(AtomicFile, ANameOfTheFileSystemsFullLengthSaves) {
  test::TempFolder folder;
  std::string cjk;
  for (int i = 0; i < 82; ++i) cjk += "\xe7\x94\xbb";  // 画, 3 bytes
  for (const std::string& name : {std::string(255, 'a'), cjk + ".impasto", cjk + "ab"}) {
    ASSERT_LE(name.size(), 255u);
    write_file_atomically(folder / name, "first");
    write_file_atomically(folder / name, "second");
    EXPECT_EQ(contents(folder / name), "second") << name.size() << " bytes";
    EXPECT_TRUE(others(folder.path(), {name}).empty()) << name.size() << " bytes";
    std::filesystem::remove(folder / name);
  }
}

// A size field known only at the end is written back in place, whether its bytes were flushed
// or still buffered; nothing past the bytes written can be overwritten.
TEST(AtomicFile, WriteAtOverwritesBytesAlreadyWritten) {
  test::TempFolder folder;
  AtomicFile out(folder / "a.bin");
  out.write("size:????");
  out.write(std::string(3 << 20, 'x'));  // more than the 1 MB buffer: the start is on disk
  out.write("tail");
  out.write_at(5, "1234", 4);
  out.write_at(out.bytes_written() - 4, "TAIL", 4);
  EXPECT_THROW(out.write_at(out.bytes_written() - 2, "abc", 3), std::logic_error);
  out.commit();
  const std::string written = contents(folder / "a.bin");
  EXPECT_EQ(written.size(), 9u + (3u << 20) + 4u);
  EXPECT_EQ(written.substr(0, 9), "size:1234");
  EXPECT_EQ(written.substr(written.size() - 4), "TAIL");
}

TEST(AtomicFile, ReplacesTheOldFile) {
  test::TempFolder folder;
  put(folder / "a.txt", "old contents");
  write_file_atomically(folder / "a.txt", "new");
  EXPECT_EQ(contents(folder / "a.txt"), "new");
}

// A full disk: the write fails after N bytes. The old file is intact, the temp file is gone,
// and the message names the file and the reason.
TEST(AtomicFile, AFullDiskLeavesTheOldFileAndNoTemp) {
  test::TempFolder folder;
  put(folder / "a.txt", "old contents");
  const std::string big(3 << 20, 'x');  // more than one buffer, so some bytes reach the disk
  for (std::uint64_t limit : {0ull, 100ull, (1ull << 20) + 7}) {
    try {
      write_file_atomically(folder / "a.txt", big, AtomicFileOptions{limit});
      FAIL() << "a save past the full disk succeeded";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("a.txt"), std::string::npos) << message;
      EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
    }
    EXPECT_EQ(contents(folder / "a.txt"), "old contents");
    EXPECT_TRUE(others(folder.path(), {"a.txt"}).empty());
  }
}

// The same through the kernel: RLIMIT_FSIZE makes write() itself fail (EFBIG).
TEST(AtomicFile, AKernelWriteErrorLeavesTheOldFileAndNoTemp) {
  test::TempFolder folder;
  put(folder / "a.txt", "old contents");
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_file_atomically(folder / "a.txt", std::string(3 << 20, 'x'));
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(message.find("a.txt: cannot save"), std::string::npos) << message;
  EXPECT_EQ(contents(folder / "a.txt"), "old contents");
  EXPECT_TRUE(others(folder.path(), {"a.txt"}).empty());
}

TEST(AtomicFile, AnExceptionWhileWritingRemovesTheTemp) {
  test::TempFolder folder;
  put(folder / "a.txt", "old");
  try {
    AtomicFile file(folder / "a.txt");
    file.write("partial");
    throw std::runtime_error("the producer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(contents(folder / "a.txt"), "old");
  EXPECT_TRUE(others(folder.path(), {"a.txt"}).empty());
}

TEST(AtomicFile, WritesThroughASymlinkToItsTarget) {
  test::TempFolder folder;
  std::filesystem::create_directory(folder / "real");
  put(folder / "real/a.txt", "old");
  std::filesystem::create_symlink("real/a.txt", folder / "link.txt");
  write_file_atomically(folder / "link.txt", "new");
  EXPECT_TRUE(std::filesystem::is_symlink(folder / "link.txt"));
  EXPECT_EQ(contents(folder / "real/a.txt"), "new");
  EXPECT_TRUE(others(folder / "real", {"a.txt"}).empty());
}

TEST(AtomicFile, ADanglingSymlinkCreatesItsTarget) {
  test::TempFolder folder;
  std::filesystem::create_symlink(folder / "made.txt", folder / "link.txt");
  write_file_atomically(folder / "link.txt", "new");
  EXPECT_TRUE(std::filesystem::is_symlink(folder / "link.txt"));
  EXPECT_EQ(contents(folder / "made.txt"), "new");
}

TEST(AtomicFile, KeepsTheMode) {
  test::TempFolder folder;
  for (mode_t mode : {0600, 0640, 0755}) {
    put(folder / "a.txt", "old");
    ASSERT_EQ(::chmod((folder / "a.txt").c_str(), mode), 0);
    write_file_atomically(folder / "a.txt", "new");
    EXPECT_EQ(mode_of(folder / "a.txt"), mode);
  }
}

TEST(AtomicFile, ANewFileFollowsTheUmask) {
  test::TempFolder folder;
  const mode_t old = ::umask(027);
  write_file_atomically(folder / "a.txt", "new");
  ::umask(old);
  EXPECT_EQ(mode_of(folder / "a.txt"), 0640u);
}

// A planted symlink at a predictable temp name is never followed: names are random and
// created exclusively; a stale temp file of a dead process is removed, a live one's is not.
TEST(AtomicFile, IgnoresPlantedTempNamesAndRemovesStaleOnes) {
  test::TempFolder folder;
  put(folder / "victim.txt", "precious");
  // pid 2^22+1 is above Linux's pid_max limit, so no process has it.
  const std::string dead = ".a.txt.impasto-tmp-4194305-0123456789abcdef";
  const std::string alive = ".a.txt.impasto-tmp-" + std::to_string(::getpid()) + "-0";
  std::filesystem::create_symlink(folder / "victim.txt", folder / dead);
  put(folder / alive, "another save of this process, in progress");
  for (int pid = ::getpid(); pid < ::getpid() + 3; ++pid)
    std::filesystem::create_symlink(folder / "victim.txt",
                                    folder / ("a.txt.tmp." + std::to_string(pid)));
  write_file_atomically(folder / "a.txt", "new");
  EXPECT_EQ(contents(folder / "a.txt"), "new");
  EXPECT_EQ(contents(folder / "victim.txt"), "precious");
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(folder / dead)));
  EXPECT_TRUE(std::filesystem::exists(folder / alive));
}

// The choice for hard links: the named file is replaced whole (never rewritten in place), so
// its other names keep the old, complete contents.
TEST(AtomicFile, AHardLinkedFileIsReplacedWholeAndTheOtherNameKeepsTheOldContents) {
  test::TempFolder folder;
  put(folder / "a.txt", "old");
  std::filesystem::create_hard_link(folder / "a.txt", folder / "b.txt");
  write_file_atomically(folder / "a.txt", "new");
  EXPECT_EQ(contents(folder / "a.txt"), "new");
  EXPECT_EQ(contents(folder / "b.txt"), "old");
}

TEST(AtomicFile, RefusesAFolderAsTargetByName) {
  test::TempFolder folder;
  std::filesystem::create_directory(folder / "dir");
  try {
    write_file_atomically(folder / "dir", "x");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("dir: cannot save: it is a folder"), std::string::npos)
        << e.what();
  }
}

TEST(AtomicFile, AReadOnlyFolderGivesAClearErrorAndKeepsTheFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  test::TempFolder folder;
  put(folder / "a.txt", "old");
  ASSERT_EQ(::chmod(folder.path().c_str(), 0500), 0);
  try {
    write_file_atomically(folder / "a.txt", "new");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos) << e.what();
  }
  ::chmod(folder.path().c_str(), 0700);
  EXPECT_EQ(contents(folder / "a.txt"), "old");
}

TEST(AtomicFile, RefusesAReadOnlyFileByName) {
  test::TempFolder folder;
  put(folder / "a.txt", "old");
  ASSERT_EQ(::chmod((folder / "a.txt").c_str(), 0444), 0);
  try {
    write_file_atomically(folder / "a.txt", "new");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a.txt: cannot save: the file is read-only (mode 0444)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(contents(folder / "a.txt"), "old");
  EXPECT_EQ(mode_of(folder / "a.txt"), 0444u);
  EXPECT_TRUE(others(folder.path(), {"a.txt"}).empty());
}

}  // namespace
}  // namespace impasto::files
