// Stroke files and HID recordings against devices and folders: refused by name before any
// read (a /dev/zero once grew to 2 GB before failing), as InputFormatError naming the file.
#include <gtest/gtest.h>

#include <filesystem>

#include "impasto/input/hid_recording.hpp"
#include "impasto/input/stroke_file.hpp"
#include "impasto/input/stroke_import.hpp"

namespace impasto::input {
namespace {

template <typename Read>
std::string error_of(const Read& read) {
  try {
    read();
  } catch (const InputFormatError& e) {
    return e.what();
  }
  return "";
}

TEST(RecordingFileSafety, DevicesAreRefusedByName) {
  EXPECT_EQ(error_of([] { read_stroke_file("/dev/zero"); }),
            "/dev/zero: cannot read the stroke file: it is a device, not a file");
  EXPECT_EQ(error_of([] { load_strokes_any("/dev/zero", ImportOptions{}); }),
            "/dev/zero: cannot read the stroke file: it is a device, not a file");
  EXPECT_EQ(error_of([] { hid::read_hid_recording("/dev/zero"); }),
            "/dev/zero: cannot read the HID recording: it is a device, not a file");
}

TEST(RecordingFileSafety, FoldersAreRefusedByName) {
  const std::string dir = std::filesystem::temp_directory_path().string();
  EXPECT_EQ(error_of([&] { read_stroke_file(dir); }),
            dir + ": cannot read the stroke file: it is a folder, not a file");
  EXPECT_EQ(error_of([&] { hid::read_hid_recording(dir); }),
            dir + ": cannot read the HID recording: it is a folder, not a file");
}

}  // namespace
}  // namespace impasto::input
