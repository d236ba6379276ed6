#pragma once
// A saved painting file's sections, decompressed, for the tests that edit a field by its offset
// (docs/painting-format.md), and a file made again around edited sections with their sizes and
// checksums put right. Version 8 compresses each section (painting_file_codec.hpp).
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

#include "hasher.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "section_codec.hpp"

namespace impasto::paintcore::test {

struct FileSections {
  std::uint32_t version = kPaintingFileVersion;
  std::vector<unsigned char> payload;
  std::optional<std::vector<unsigned char>> history;
};

namespace sections_detail {

template <typename T>
T read_at(const std::vector<unsigned char>& bytes, std::size_t at) {
  if (at + sizeof(T) > bytes.size()) throw std::runtime_error("test file: truncated");
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  return value;
}

template <typename T>
void append(std::vector<unsigned char>& bytes, const T& value) {
  const auto* p = reinterpret_cast<const unsigned char*>(&value);
  bytes.insert(bytes.end(), p, p + sizeof(T));
}

// One compressed section at `at`; returns it decompressed and moves `at` past it.
inline std::vector<unsigned char> take_section(const std::vector<unsigned char>& file,
                                               std::size_t& at) {
  const auto stored = read_at<std::uint64_t>(file, at);
  const auto size = read_at<std::uint64_t>(file, at + 8);
  if (at + 16 + stored + 8 > file.size()) throw std::runtime_error("test file: truncated section");
  const std::span<const unsigned char> frame(file.data() + at + 16, stored);
  at += 16 + stored + 8;
  return file_io::decompress_section(frame, size);
}

inline void put_section(std::vector<unsigned char>& file,
                        const std::vector<unsigned char>& section) {
  const std::vector<unsigned char> stored = file_io::compress_section(section);
  append(file, static_cast<std::uint64_t>(stored.size()));
  append(file, static_cast<std::uint64_t>(section.size()));
  file.insert(file.end(), stored.begin(), stored.end());
  StreamHasher checksum;
  checksum.bytes(stored.data(), stored.size());
  append(file, checksum.digest());
}

}  // namespace sections_detail

// The sections of a version-8 file.
inline FileSections sections_of(const std::vector<unsigned char>& file) {
  FileSections s;
  s.version = sections_detail::read_at<std::uint32_t>(file, kPaintingFileMagicBytes);
  std::size_t at = kPaintingFileMagicBytes + 4;
  s.payload = sections_detail::take_section(file, at);
  if (at < file.size()) s.history = sections_detail::take_section(file, at);
  return s;
}

// A version-8 file around the sections, every size and checksum matching.
inline std::vector<unsigned char> file_of(const FileSections& s) {
  std::vector<unsigned char> file = {'I', 'M', 'P', 'A', 'S', 'T', 'O', '\0'};
  sections_detail::append(file, s.version);
  sections_detail::put_section(file, s.payload);
  if (s.history) sections_detail::put_section(file, *s.history);
  return file;
}

}  // namespace impasto::paintcore::test
