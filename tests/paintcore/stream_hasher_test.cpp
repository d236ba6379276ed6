// The painting file's checksum over a range given in pieces (StreamHasher: the file read or
// written in chunks) is the hash of the whole range, however it is cut.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "hasher.hpp"

namespace impasto::paintcore {
namespace {

TEST(StreamHasher, AnyCutGivesTheWholeRangesHash) {
  std::mt19937 random(7);
  std::vector<unsigned char> bytes(5000);
  for (unsigned char& b : bytes) b = static_cast<unsigned char>(random());
  for (std::size_t size : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{8},
                           std::size_t{9}, std::size_t{4096}, bytes.size()}) {
    Hasher whole;
    whole.bytes(bytes.data(), size);
    for (int cut = 0; cut < 50; ++cut) {
      StreamHasher pieces;
      for (std::size_t at = 0; at < size;) {
        const std::size_t piece = std::min<std::size_t>(size - at, random() % 23);  // 0 too
        pieces.bytes(bytes.data() + at, piece);
        at += piece;
      }
      pieces.bytes(nullptr, 0);
      ASSERT_EQ(pieces.digest(), whole.digest()) << size << " bytes, cut " << cut;
    }
  }
}

}  // namespace
}  // namespace impasto::paintcore
