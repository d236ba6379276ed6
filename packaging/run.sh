#!/usr/bin/env bash
# Installs what is missing, builds Impasto, and runs it: the painting window where a display
# exists; headless, it replays the bundled demo strokes and writes demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j "$(nproc)" --target impasto
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && ./build/release/app/impasto paint --help >/dev/null 2>&1; then
  exec ./build/release/app/impasto paint "$@"
fi
./build/release/app/impasto replay data/strokes/demo.dat --json -o demo.png "$@"
echo "wrote $(pwd)/demo.png"
