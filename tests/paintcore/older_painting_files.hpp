#pragma once
// Painting files of older format versions, made from what save() writes today, for the tests
// that check they still load (docs/painting-format.md): the payload taken out of a saved file,
// one version's additions taken away, and a file written around a payload.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "hasher.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "impasto/paintcore/simulation_params.hpp"
#include "painting_file_sections.hpp"

namespace impasto::paintcore::test {

// Where the parameters begin in a payload of version 5 or later: after the canvas's size, dpi
// and weave seed (24 bytes) and the weave's origin (2 × i64).
inline constexpr std::size_t kParamsOffset = 4 + 4 + 8 + 8 + 2 * 8;

// The payload of a saved file's bytes, decompressed (the undo history may follow it).
inline std::vector<unsigned char> payload_of(const std::vector<unsigned char>& file_bytes) {
  return sections_of(file_bytes).payload;
}

// A payload of `version` (5 or later) from today's (versions 5 to 9 lay the payload out alike
// but for the parameters each added, after the others): without the parameters added since.
inline std::vector<unsigned char> without_params_after(std::vector<unsigned char> payload,
                                                       std::uint32_t version) {
  const auto kept = static_cast<std::ptrdiff_t>(8 * simulation_param_fields(version).size());
  const auto added =
      static_cast<std::ptrdiff_t>(8 * simulation_param_fields(kPaintingFileVersion).size()) - kept;
  const auto at = payload.begin() + static_cast<std::ptrdiff_t>(kParamsOffset) + kept;
  payload.erase(at, at + added);
  return payload;
}

// A version-6 payload from today's: without the long steps' settings (version 7) and later.
inline std::vector<unsigned char> as_version_six(std::vector<unsigned char> payload) {
  return without_params_after(std::move(payload), 6);
}

// Writes a painting file of `version` around `payload`, with the payload's checksum: as
// versions 1 to 7 stored it (u64 size, the payload, its checksum), compressed from version 8.
inline void write_painting_file(const std::filesystem::path& file, std::uint32_t version,
                                const std::vector<unsigned char>& payload) {
  std::vector<unsigned char> bytes;
  if (version >= 8) {
    bytes = file_of(FileSections{version, payload, std::nullopt});
  } else {
    bytes = {'I', 'M', 'P', 'A', 'S', 'T', 'O', '\0'};
    bytes.resize(kPaintingFileHeaderBytes);
    std::memcpy(bytes.data() + 8, &version, 4);
    const std::uint64_t size = payload.size();
    std::memcpy(bytes.data() + 12, &size, 8);
    bytes.insert(bytes.end(), payload.begin(), payload.end());
    Hasher checksum;
    checksum.bytes(payload.data(), payload.size());
    const std::uint64_t digest = checksum.digest();
    bytes.resize(bytes.size() + 8);
    std::memcpy(bytes.data() + bytes.size() - 8, &digest, 8);
  }
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

}  // namespace impasto::paintcore::test
