#pragma once
// How version 8 stores a section of the painting file (the payload, the undo history): the
// section's bytes, laid out as before, cut into blocks of kCodecBlockBytes whose 4-byte lanes
// are shuffled (every value's first byte, then every second byte, ...: the floats' exponents
// and high mantissa bits line up into runs), then compressed as one zstd frame. On disk:
//   u64 stored size, u64 section size, the frame, u64 checksum of the frame's bytes.
// Tile records are 4-byte values from a 4-byte boundary, so the lanes line up whatever the
// fields before them; a block that is not a multiple of 4 keeps its tail unshuffled.
// painting_file_codec.hpp streams sections; this header is what tests and tools need.
#include <cstdint>
#include <span>
#include <vector>

namespace impasto::paintcore::file_io {

inline constexpr std::size_t kCodecBlockBytes = 64 << 10;

// The lane shuffle of one block of `bytes` bytes, and its inverse.
void shuffle_lanes(const unsigned char* in, std::size_t bytes, unsigned char* out);
void unshuffle_lanes(const unsigned char* in, std::size_t bytes, unsigned char* out);

// A whole section at once (tests and tools that edit a saved file's fields).
std::vector<unsigned char> compress_section(std::span<const unsigned char> section);
std::vector<unsigned char> decompress_section(std::span<const unsigned char> stored,
                                              std::uint64_t section_bytes);

}  // namespace impasto::paintcore::file_io
