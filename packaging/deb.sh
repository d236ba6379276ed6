#!/usr/bin/env bash
# Builds the Debian packages from an existing build folder (default build/release), rebuilding
# only what they hold: build/release/package/impasto_VERSION_ARCH.deb and, where the Python
# module is built, python3-impasto_VERSION_ARCH.deb.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
if [ ! -f "$build/CMakeCache.txt" ]; then  # a fresh clone: install what is missing, configure
  bash packaging/deps.sh
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
targets=(impasto impasto_man_page impasto_changelog)
if cmake --build "$build" --target help | grep -q "^impasto_python:"; then
  targets+=(impasto_python)
fi
cmake --build "$build" --target "${targets[@]}"
rm -f "$build"/package/impasto_*.deb "$build"/package/python3-impasto_*.deb
(cd "$build" && cpack -G DEB --config CPackConfig.cmake >/dev/null)
ls "$build"/package/impasto_*.deb
ls "$build"/package/python3-impasto_*.deb 2>/dev/null || true
# Debian's package checker, where it is installed (apt-get install lintian): CI does not
# install it, to keep its time; packaging changes are checked with it before they land.
if command -v lintian >/dev/null; then
  status=0
  report="$(lintian --fail-on error,warning --pedantic "$build"/package/impasto_*.deb \
    $(ls "$build"/package/python3-impasto_*.deb 2>/dev/null) 2>&1)" ||
    status=$?
  grep -v "running with root privileges" <<<"$report" || true
  exit "$status"
fi
