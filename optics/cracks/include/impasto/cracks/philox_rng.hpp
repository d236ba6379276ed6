#pragma once
// Philox-4x32-10 (Salmon, Moraes, Dror, Shaw, "Parallel random numbers: as easy as 1, 2,
// 3", SC 2011): a counter-based generator. A random block is a pure function of a 128-bit
// counter and a 64-bit key, so every Monte Carlo path draws its numbers from its own
// counter (path index, bounce) and results do not depend on threads or on scheduling.
#include <array>
#include <cstdint>

namespace impasto::cracks {

using PhiloxCounter = std::array<std::uint32_t, 4>;
using PhiloxKey = std::array<std::uint32_t, 2>;

constexpr PhiloxCounter philox4x32_10(PhiloxCounter ctr, PhiloxKey key) {
  constexpr std::uint32_t kMul0 = 0xD2511F53u, kMul1 = 0xCD9E8D57u;
  constexpr std::uint32_t kWeyl0 = 0x9E3779B9u, kWeyl1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    if (round > 0) {
      key[0] += kWeyl0;
      key[1] += kWeyl1;
    }
    const std::uint64_t p0 = std::uint64_t{kMul0} * ctr[0];
    const std::uint64_t p1 = std::uint64_t{kMul1} * ctr[2];
    ctr = {static_cast<std::uint32_t>(p1 >> 32) ^ ctr[1] ^ key[0], static_cast<std::uint32_t>(p1),
           static_cast<std::uint32_t>(p0 >> 32) ^ ctr[3] ^ key[1], static_cast<std::uint32_t>(p0)};
  }
  return ctr;
}

// A uniform number in the open interval (0, 1) from 32 random bits.
constexpr double unit_open(std::uint32_t bits) {
  return (bits + 0.5) * 0x1p-32;
}

// Four uniforms in (0, 1) for (seed, stream, index, step): one Philox block.
struct UniformBlock {
  std::array<double, 4> u;
};
constexpr UniformBlock uniforms(std::uint64_t seed, std::uint32_t stream, std::uint64_t index,
                                std::uint32_t step) {
  const PhiloxCounter out = philox4x32_10(
      {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32), step, stream},
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
  return {{unit_open(out[0]), unit_open(out[1]), unit_open(out[2]), unit_open(out[3])}};
}

}  // namespace impasto::cracks
