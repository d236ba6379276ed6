#!/usr/bin/env bash
# Builds Impasto and runs every test twice: a Release build with warnings as errors (and its
# Debian package, unpacked and run: packaging/smoke-test.sh), then a build under
# AddressSanitizer + UndefinedBehaviorSanitizer; then a short libFuzzer run of the file and
# HID parsers (IMPASTO_FUZZ_SECONDS per target, default 5; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/deps.sh
jobs="$(nproc)"
export CTEST_OUTPUT_ON_FAILURE=1

cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DIMPASTO_WERROR=ON
cmake --build build/release -j "$jobs"
ctest --test-dir build/release -j "$jobs" --timeout 600 | tee build/release/ctest.log
# The Debian package from the same build, unpacked and run with no source tree to lean on.
bash packaging/deb.sh build/release
bash packaging/deb-okumura.sh build/release/package
bash packaging/smoke-test.sh build/release/package/impasto_*.deb \
  build/release/package/impasto-pigments-okumura_*.deb

# -O1 -g1 replace Debug's own -g (in CMAKE_CXX_FLAGS they came first, and -g overrode -g1).
cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DIMPASTO_WERROR=ON -DIMPASTO_SANITIZE=ON -DIMPASTO_BUILD_BENCHMARKS=OFF
cmake --build build/sanitize -j "$jobs"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir build/sanitize -j "$jobs" --timeout 900 -LE "no-sanitize" | tee build/sanitize/ctest.log

fuzz_seconds="${IMPASTO_FUZZ_SECONDS:-5}"
if [ "$fuzz_seconds" -gt 0 ]; then
  bash tests/fuzz/run.sh "$fuzz_seconds"
fi

# One closing line for both test runs (reached only when every test passed).
count() { sed -n 's/.*tests failed out of \([0-9][0-9]*\).*/\1/p' "$1" | tail -n 1; }
echo "all: $(($(count build/release/ctest.log) + $(count build/sanitize/ctest.log))) passed, 0 failed"
