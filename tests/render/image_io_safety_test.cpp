// Images written atomically (PNG and EXR through symlinks, keeping the mode; a full disk leaves
// the old file) and PNGs read with their declared size checked first (docs/guarantees.md).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "impasto/render/image.hpp"

namespace impasto::render {
namespace {

namespace fs = std::filesystem;

class ImageIoSafetyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("impasto_image_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static Image grey(int w, int h, float v) {
    return Image{w, h, std::vector<float>(3 * static_cast<std::size_t>(w) * h, v)};
  }
  static std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  fs::path dir_;
};

TEST_F(ImageIoSafetyTest, WritesThroughSymlinksKeepingTheMode) {
  for (const char* name : {"real.png", "real.exr"}) {
    std::ofstream(dir_ / name) << "old";
    ASSERT_EQ(::chmod((dir_ / name).c_str(), 0640), 0);
    const fs::path link = dir_ / (std::string("link") + fs::path(name).extension().string());
    fs::create_symlink(name, link);
    if (fs::path(name).extension() == ".png")
      write_png(link, grey(5, 4, 0.5f));
    else
      write_exr(link, grey(5, 4, 0.5f));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_NE(contents(dir_ / name), "old");
    struct stat st {};
    ASSERT_EQ(::stat((dir_ / name).c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u) << name;
  }
  EXPECT_EQ(read_png(dir_ / "real.png").width, 5);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 4);  // no temp file left
}

TEST_F(ImageIoSafetyTest, AFullDiskLeavesTheOldImage) {
  write_png(dir_ / "a.png", grey(8, 8, 0.25f));
  const std::string old = contents(dir_ / "a.png");
  rlimit limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &limit), 0);
  const auto handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = limit;
  small.rlim_cur = 100;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  try {
    // Noise does not compress: well over 100 bytes.
    Image noisy = grey(64, 64, 0.0f);
    for (std::size_t i = 0; i < noisy.rgb.size(); ++i)
      noisy.rgb[i] = static_cast<float>((i * 2654435761u) % 251) / 250.0f;
    write_png(dir_ / "a.png", noisy);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &limit);
  std::signal(SIGXFSZ, handler);
  EXPECT_NE(error.find("a.png: cannot save"), std::string::npos) << error;
  EXPECT_EQ(contents(dir_ / "a.png"), old);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 1);
}

TEST_F(ImageIoSafetyTest, AHugeDeclaredPngIsRefusedBeforeDecoding) {
  const fs::path file =
      fs::path(IMPASTO_SOURCE_DIR) / "tests/fuzz/corpus/images/ihdr_100000x100000.png";
  try {
    read_png(file);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("IHDR width x height 100000 x 100000"), std::string::npos)
        << e.what();
  }
  try {
    read_png("/dev/zero");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "/dev/zero: cannot read the PNG image: it is a device, not a file");
  }
}

}  // namespace
}  // namespace impasto::render
