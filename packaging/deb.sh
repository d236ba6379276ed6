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
cmake --build "$build" --target impasto impasto_man_page impasto_changelog
rm -f "$build"/package/impasto_*.deb
(cd "$build" && cpack -G DEB --config CPackConfig.cmake >/dev/null)
ls "$build"/package/impasto_*.deb
# Debian's package checker, where it is installed (apt-get install lintian): CI does not
# install it, to keep its time; packaging changes are checked with it before they land.
if command -v lintian >/dev/null; then
  status=0
  report="$(lintian --fail-on error,warning --pedantic "$build"/package/impasto_*.deb 2>&1)" ||
    status=$?
  grep -v "running with root privileges" <<<"$report" || true
  exit "$status"
fi
