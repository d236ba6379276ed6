#!/usr/bin/env bash
# Builds the Debian package from an existing build folder (default build/release), rebuilding
# only what the package holds: build/release/package/impasto_VERSION_ARCH.deb.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
if [ ! -f "$build/CMakeCache.txt" ]; then  # a fresh clone: install what is missing, configure
  bash packaging/deps.sh
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target impasto impasto_man_page
rm -f "$build"/package/impasto_*.deb
(cd "$build" && cpack -G DEB --config CPackConfig.cmake >/dev/null)
ls "$build"/package/impasto_*.deb
