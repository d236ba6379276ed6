// Crack maps as PNG files against hostile inputs: a 68-byte header declaring 100000 x 100000
// pixels, devices and folders; and saved atomically through symlinks (docs/guarantees.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "impasto/cracks/craquelure.hpp"

namespace impasto::cracks {
namespace {

namespace fs = std::filesystem;

std::string read_error(const fs::path& file) {
  try {
    read_crack_png(file, CrackImageSettings{});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CrackPngSafety, AHugeDeclaredSizeIsRefusedBeforeDecoding) {
  const fs::path file =
      fs::path(IMPASTO_SOURCE_DIR) / "tests/fuzz/corpus/images/ihdr_100000x100000.png";
  const std::string error = read_error(file);
  EXPECT_NE(error.find(file.string() + ": the header's size (IHDR width x height 100000 x 100000)"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("more than a file of 68 bytes can hold"), std::string::npos) << error;
}

TEST(CrackPngSafety, DevicesAndFoldersAreRefusedByName) {
  EXPECT_EQ(read_error("/dev/zero"),
            "/dev/zero: cannot read the PNG crack map: it is a device, not a file");
  EXPECT_EQ(read_error(fs::temp_directory_path()),
            fs::temp_directory_path().string() +
                ": cannot read the PNG crack map: it is a folder, not a file");
}

TEST(CrackPngSafety, SavesThroughASymlinkAndReadsBack) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_crack_png_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "real.png") << "old";
  fs::create_symlink("real.png", dir / "link.png");
  CrackMap map(70, 20, 0.1);
  map.set(3, 4, CrackCell{0.25f, 0.05f});
  write_crack_png(map, dir / "link.png", 0.5);
  EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
  const CrackMap back = read_crack_png(dir / "real.png", CrackImageSettings{});
  EXPECT_EQ(back.width(), 70);
  EXPECT_NEAR(back.at(3, 4).depth_mm, 0.25f, 1e-4f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 2);  // no temp file left
  fs::remove_all(dir);
}

}  // namespace
}  // namespace impasto::cracks
