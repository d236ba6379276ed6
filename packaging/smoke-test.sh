#!/usr/bin/env bash
# Unpacks the Debian package into a temporary root (no apt, no root) and runs the installed
# impasto from there, in an empty folder, with $IMPASTO_DATA_DIR unset: it must find its data
# beside itself (usr/bin/../share/impasto), as after a moved install prefix. An installed copy
# never reads the source tree (files::data_dir), so a missing file fails here.
set -euo pipefail
deb="$(realpath "${1:?usage: smoke-test.sh IMPASTO.deb}")"
root="$(mktemp -d)"
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root/unpacked"
mkdir "$root/work"
cd "$root/work"
impasto="$root/unpacked/usr/bin/impasto"
unset IMPASTO_DATA_DIR
export XDG_DATA_HOME="$root/xdg-data" XDG_CONFIG_HOME="$root/xdg-config" \
  XDG_STATE_HOME="$root/xdg-state"

# What the package must hold besides the program and its data.
for file in usr/share/applications/impasto.desktop usr/share/mime/packages/impasto.xml \
  usr/share/thumbnailers/impasto.thumbnailer usr/share/icons/hicolor/scalable/apps/impasto.svg \
  usr/share/icons/hicolor/48x48/apps/impasto.png usr/lib/udev/rules.d/70-impasto-tablets.rules \
  usr/share/man/man1/impasto.1.gz usr/share/impasto/brushes/round.brush \
  usr/share/doc/impasto/copyright usr/share/doc/impasto/NOTICE; do
  [ -f "$root/unpacked/$file" ] || { echo "smoke test: the package lacks /$file" >&2; exit 1; }
done
dpkg-deb -f "$deb" Depends | grep -q libtbb || { echo "smoke test: no shlibdeps" >&2; exit 1; }

"$impasto" --version | grep -q "Apache License 2.0" ||
  { echo "smoke test: impasto --version does not name the licence" >&2; exit 1; }
"$impasto" pigments list >/dev/null
"$impasto" replay "$root/unpacked/usr/share/impasto/strokes/demo.dat" --save demo.impasto \
  -o demo.png >/dev/null
"$impasto" render demo.impasto --out relit.png --light A --wavelengths 4 >/dev/null
"$impasto" thumbnail demo.impasto thumb.png 128
for png in demo.png relit.png thumb.png; do
  [ -s "$png" ] || { echo "smoke test: $png was not written" >&2; exit 1; }
done
echo "smoke test: $(basename "$deb") runs from an unpacked root (replay, render, thumbnail)"
