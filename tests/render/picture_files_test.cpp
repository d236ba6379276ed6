// Pictures a user opens (the window's reference image): PNG and JPEG, told apart by their first
// bytes; JPEG sizes checked before decoding, damaged and CMYK files named.
#include <gtest/gtest.h>
#include <turbojpeg.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "impasto/render/image.hpp"

namespace impasto::render {
namespace {

namespace fs = std::filesystem;

class PictureFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("impasto_pictures_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A smooth gradient: red across, green down, blue constant.
  static std::vector<unsigned char> gradient(int w, int h) {
    std::vector<unsigned char> rgb(3 * static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        unsigned char* p = rgb.data() + 3 * (static_cast<std::size_t>(y) * w + x);
        p[0] = static_cast<unsigned char>(255 * x / (w - 1));
        p[1] = static_cast<unsigned char>(255 * y / (h - 1));
        p[2] = 96;
      }
    return rgb;
  }
  // Encodes pixels of `format` (TJPF_RGB or TJPF_CMYK) as a JPEG file's bytes.
  static std::string encode(const std::vector<unsigned char>& pixels, int w, int h, int format,
                            int flags = 0) {
    tjhandle handle = tjInitCompress();
    unsigned char* jpeg = nullptr;
    unsigned long size = 0;
    const int failed =
        tjCompress2(handle, pixels.data(), w, 0, h, format, &jpeg, &size, TJSAMP_444, 95, flags);
    std::string bytes = failed ? std::string() : std::string(reinterpret_cast<char*>(jpeg), size);
    tjFree(jpeg);
    tjDestroy(handle);
    return bytes;
  }
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }
  static std::string error_of(const fs::path& file) {
    try {
      read_picture(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

TEST_F(PictureFiles, AJpegReadsBackAsItsPixelsWhateverItsName) {
  const int w = 40, h = 24;
  const std::vector<unsigned char> rgb = gradient(w, h);
  const std::string bytes = encode(rgb, w, h, TJPF_RGB);
  ASSERT_FALSE(bytes.empty());
  for (const char* name : {"photo.jpg", "photo.JPEG", "photo.png", "photo"}) {
    const Image image = read_picture(write(name, bytes));
    ASSERT_EQ(image.width, w) << name;
    ASSERT_EQ(image.height, h) << name;
    double worst = 0.0;
    for (std::size_t i = 0; i < rgb.size(); ++i)
      worst = std::max(worst, std::abs(image.rgb[i] * 255.0 - rgb[i]));
    EXPECT_LT(worst, 8.0) << name << ": quality 95 keeps a smooth gradient within a few levels";
  }
  // A progressive file reads the same.
  const Image progressive =
      read_jpeg(write("p.jpg", encode(rgb, w, h, TJPF_RGB, TJFLAG_PROGRESSIVE)));
  EXPECT_EQ(progressive.width, w);
  EXPECT_NEAR(progressive.rgb[3 * (w - 1)] * 255.0, 255.0, 8.0);
}

TEST_F(PictureFiles, APngIsReadAsAPngWhateverItsName) {
  Image image{3, 2, std::vector<float>(18, 0.0f)};
  image.rgb[0] = 1.0f;
  write_png(dir_ / "a.png", image);
  fs::rename(dir_ / "a.png", dir_ / "a.jpg");
  const Image back = read_picture(dir_ / "a.jpg");
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.rgb[0], 1.0f);
  EXPECT_EQ(back.rgb[3], 0.0f);
}

TEST_F(PictureFiles, AnythingElseIsNamed) {
  const std::string error = error_of(write("notes.jpg", "just some text, not a picture"));
  EXPECT_NE(error.find("notes.jpg"), std::string::npos) << error;
  EXPECT_NE(error.find("not a PNG or JPEG"), std::string::npos) << error;
  EXPECT_NE(error_of(dir_ / "missing.jpg").find("missing.jpg"), std::string::npos);
}

TEST_F(PictureFiles, AHugeDeclaredSizeIsRefusedBeforeDecoding) {
  std::string bytes = encode(gradient(16, 16), 16, 16, TJPF_RGB);
  // The frame header (SOF0, FF C0): length, precision, then height and width, big-endian.
  const std::size_t sof = bytes.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  for (const std::size_t at : {sof + 5, sof + 7}) {  // 65000 x 65000 pixels
    bytes[at] = static_cast<char>(0xFD);
    bytes[at + 1] = static_cast<char>(0xE8);
  }
  const std::string error = error_of(write("huge.jpg", bytes));
  EXPECT_NE(error.find("huge.jpg"), std::string::npos) << error;
  EXPECT_NE(error.find("65000 x 65000"), std::string::npos) << error;
}

TEST_F(PictureFiles, DamagedAndCmykFilesAreNamed) {
  const std::vector<unsigned char> rgb = gradient(32, 32);
  std::string bytes = encode(rgb, 32, 32, TJPF_RGB);
  // Cut short after its headers: libjpeg-turbo fills the rest (a warning, as a real truncated
  // download is), so the picture opens at its size.
  const Image cut = read_picture(write("cut.jpg", bytes.substr(0, bytes.size() * 2 / 3)));
  EXPECT_EQ(cut.width, 32);
  // Headers destroyed: refused, naming the file.
  std::string broken = bytes.substr(0, 4) + std::string(200, '\x55');
  const std::string error = error_of(write("broken.jpg", broken));
  EXPECT_NE(error.find("broken.jpg: cannot read JPEG"), std::string::npos) << error;
  // A print file in CMYK.
  std::vector<unsigned char> cmyk(4 * 32 * 32, 40);
  const std::string cmyk_bytes = encode(cmyk, 32, 32, TJPF_CMYK);
  ASSERT_FALSE(cmyk_bytes.empty());
  const std::string cmyk_error = error_of(write("print.jpg", cmyk_bytes));
  EXPECT_NE(cmyk_error.find("CMYK"), std::string::npos) << cmyk_error;
}

}  // namespace
}  // namespace impasto::render
