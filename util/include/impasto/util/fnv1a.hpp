#pragma once
// FNV-1a, 64 bits: a small, stable hash of bytes for cache keys and record names (the same
// bytes give the same value on every run and machine of one endianness). Not for long
// ranges (files' checksums, state hashes, large arrays): util::Hasher (hasher.hpp) takes a
// word a step and is about 5x faster there.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace impasto::util {

class Fnv1a {
 public:
  static constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;
  static constexpr std::uint64_t kPrime = 1099511628211ull;

  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value_ = (value_ ^ bytes[i]) * kPrime;
  }
  std::uint64_t value() const { return value_; }

 private:
  std::uint64_t value_ = kOffsetBasis;
};

// FNV-1a of the bytes of `text`.
std::uint64_t fnv1a(std::string_view text);

}  // namespace impasto::util
