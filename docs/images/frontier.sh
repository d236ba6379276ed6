#!/bin/sh
# Remakes docs/images/frontier.svg (docs/color-accuracy.md, "The speed/accuracy frontier") and
# prints its table: every node count, rule and storage under D65, A and F11 on the 521 bench
# samples. Run from the source tree after building: sh docs/images/frontier.sh [build folder]
set -e
build=${1:-build/release}
"$build/app/impasto" bench frontier --nodes 3 4 6 8 12 16 --lights D65 A F11 \
  --svg docs/images/frontier.svg
