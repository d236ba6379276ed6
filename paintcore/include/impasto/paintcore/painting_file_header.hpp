#pragma once
// The painting file's fixed header, for code that reads or edits a saved file's bytes (the
// loader, and the tests and fuzzer that craft hostile files): the magic, the format version
// (u32) and the payload's size (u64), little-endian, before the payload. From version 8 that
// size is the compressed payload's, and the payload's own size follows it.
#include <cstddef>
#include <cstdint>

namespace impasto::paintcore {

// The version this program writes (painting_file_io.hpp says what each version added).
inline constexpr std::uint32_t kPaintingFileVersion = 9;
inline constexpr std::size_t kPaintingFileMagicBytes = 8;  // "IMPASTO\0"
inline constexpr std::size_t kPaintingFileHeaderBytes = kPaintingFileMagicBytes + 4 + 8;

}  // namespace impasto::paintcore
