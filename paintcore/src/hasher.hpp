#pragma once
// paintcore's hashes (state hashes, file checksums): util::Hasher, and StreamHasher for a
// range given in pieces.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "impasto/util/hasher.hpp"

namespace impasto::paintcore {

using util::Hasher;

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
      hasher_.word(word);
      pending_size_ = 0;
    }
    // Whole words straight from the data (as fast as Hasher::bytes), the tail kept.
    for (; size >= 8; p += 8, size -= 8) {
      std::uint64_t word;
      std::memcpy(&word, p, 8);
      hasher_.word(word);
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
