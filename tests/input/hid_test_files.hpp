#pragma once
// The recorded HID files the hid tests read (tests/data/files/hid) and the shipped tablet
// model table.
#include <impasto/input/hid_models.hpp>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace impasto::input::hid::test {

inline const std::string kFiles = IMPASTO_TEST_FILES_DIR "/hid/";
// Real DIGImend captures: usbhid-dump descriptors and streams, string descriptor probes.
inline const std::string kH610 = kFiles + "captures/Huion_H610/";
inline const std::string kM708 = kFiles + "captures/Ugee_M708_v2/";

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// data/tablets/models.tsv, read once.
inline const std::vector<TabletModel>& models() {
  static const std::vector<TabletModel> table =
      load_tablet_models(IMPASTO_SOURCE_DIR "/data/tablets/models.tsv");
  return table;
}

}  // namespace impasto::input::hid::test
