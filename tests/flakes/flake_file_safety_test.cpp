// Flake paint files against hostile contents: the n,k table path confined to the flake file's
// folder, devices and folders refused by name (docs/guarantees.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "impasto/flakes/flake_file.hpp"

namespace impasto::flakes {
namespace {

namespace fs = std::filesystem;

std::string load_error(const fs::path& file) {
  try {
    load_flake_paint(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The real aluminium paint with its table path replaced.
void write_paint(const fs::path& file, const std::string& table) {
  std::ifstream in(fs::path(IMPASTO_SOURCE_DIR) / "data/flakes/aluminium_flakes.flake");
  std::ofstream out(file);
  for (std::string line; std::getline(in, line);)
    out << (line.rfind("nk_table", 0) == 0 ? "nk_table = " + table : line) << '\n';
}

TEST(FlakeFileSafety, TheNkTableStaysBesideTheFlakeFile) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_flake_nk_" + std::to_string(::getpid()));
  fs::create_directories(dir / "lib");
  fs::copy_file(fs::path(IMPASTO_SOURCE_DIR) / "data/flakes/aluminium_rakic1998_ld.csv",
                dir / "lib/al.csv");
  write_paint(dir / "lib/p.flake", "al.csv");
  EXPECT_EQ(load_error(dir / "lib/p.flake"), "");
  write_paint(dir / "lib/p.flake", "/etc/passwd");
  EXPECT_NE(load_error(dir / "lib/p.flake")
                .find("p.flake:18: nk_table: '/etc/passwd' is an absolute path"),
            std::string::npos)
      << load_error(dir / "lib/p.flake");
  write_paint(dir / "lib/p.flake", "../al.csv");
  EXPECT_NE(load_error(dir / "lib/p.flake").find("climbs out"), std::string::npos);
  fs::create_symlink("/etc/passwd", dir / "lib/out.csv");
  write_paint(dir / "lib/p.flake", "out.csv");
  EXPECT_NE(load_error(dir / "lib/p.flake").find("through a symlink"), std::string::npos);
  fs::remove_all(dir);
}

TEST(FlakeFileSafety, DevicesAndFoldersAreRefusedByName) {
  EXPECT_EQ(load_error("/dev/zero"),
            "/dev/zero: cannot read the flake paint file: it is a device, not a file");
  EXPECT_EQ(load_error(fs::temp_directory_path()),
            fs::temp_directory_path().string() +
                ": cannot read the flake paint file: it is a folder, not a file");
  try {
    load_nk_table("/dev/zero");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "/dev/zero: cannot read the n,k table: it is a device, not a file");
  }
}

}  // namespace
}  // namespace impasto::flakes
