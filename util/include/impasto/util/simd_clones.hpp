#pragma once
// Hot loops are compiled twice, for AVX2 and for the baseline x86-64, and the loader picks
// one for the CPU at start-up: the binary runs everywhere and uses 8-wide vectors (and
// gathers) where they exist. Only element-wise IEEE operations are vectorised and FMA is not
// enabled, so both versions give bit-identical results. Used by paintcore's row kernels and
// render's spectral kernels.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(IMPASTO_NO_SIMD_CLONES)
#define IMPASTO_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define IMPASTO_SIMD_CLONES
#endif

namespace impasto::util {

// std::min and std::max return references, and a loop that picks between two addresses
// cannot be vectorised; these return values (the same results).
inline float lesser(float a, float b) {
  return b < a ? b : a;
}
inline float greater(float a, float b) {
  return a < b ? b : a;
}

}  // namespace impasto::util
