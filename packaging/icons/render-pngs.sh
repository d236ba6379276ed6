#!/usr/bin/env bash
# Renders the PNG sizes of the icon from impasto.svg (needs rsvg-convert, Debian librsvg2-bin).
# Run after changing the SVG and commit the PNGs: the package build does not need rsvg.
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 32 48 64 128 256; do
  rsvg-convert -w "$size" -h "$size" impasto.svg -o "impasto-$size.png"
done
