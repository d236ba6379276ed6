#pragma once
// A fast 64-bit hash of byte ranges, used for state hashes and file checksums. Not
// cryptographic; stable across runs and platforms of the same endianness.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace impasto::paintcore {

class Hasher {
  friend class StreamHasher;

 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    while (size >= 8) {
      std::uint64_t word;
      std::memcpy(&word, p, 8);
      add(word);
      p += 8;
      size -= 8;
    }
    std::uint64_t tail = 0;
    if (size > 0) std::memcpy(&tail, p, size);  // (an empty vector's data() may be null)
    add(tail ^ (static_cast<std::uint64_t>(size) << 56));
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

 private:
  void add(std::uint64_t word) {
    state_ = (state_ ^ (word * 0x9e3779b97f4a7c15ull)) * 0xbf58476d1ce4e5b9ull;
    state_ ^= state_ >> 29;
  }
  std::uint64_t state_ = 0x6a09e667f3bcc909ull;
};

// Hasher::bytes over a range given in pieces (a file read or written in chunks): the same
// digest as one call over the whole range.
class StreamHasher {
 public:
  void bytes(const void* data, std::size_t size) {
    if (size == 0) return;  // (an empty vector's data() may be null)
    const auto* p = static_cast<const unsigned char*>(data);
    if (pending_size_ > 0) {  // complete the word a previous piece began
      const std::size_t take = std::min(size, sizeof(pending_) - pending_size_);
      std::memcpy(pending_ + pending_size_, p, take);
      pending_size_ += take;
      p += take;
      size -= take;
      if (pending_size_ < sizeof(pending_)) return;
      std::uint64_t word;
      std::memcpy(&word, pending_, 8);
      hasher_.add(word);
      pending_size_ = 0;
    }
    // Whole words straight from the data (as fast as Hasher::bytes), the tail kept.
    for (; size >= 8; p += 8, size -= 8) {
      std::uint64_t word;
      std::memcpy(&word, p, 8);
      hasher_.add(word);
    }
    if (size > 0) std::memcpy(pending_, p, size);
    pending_size_ = size;
  }
  std::uint64_t digest() const {
    Hasher last = hasher_;
    last.bytes(pending_, pending_size_);  // the tail word, as Hasher::bytes ends
    return last.digest();
  }

 private:
  Hasher hasher_;
  unsigned char pending_[8] = {};
  std::size_t pending_size_ = 0;
};

}  // namespace impasto::paintcore
