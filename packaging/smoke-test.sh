#!/usr/bin/env bash
# Unpacks the Debian package into a temporary root (no apt, no root) and runs the installed
# impasto from there, in an empty folder, with $IMPASTO_DATA_DIR unset: it must find its data
# beside itself (usr/bin/../share/impasto), as after a moved install prefix. An installed copy
# never reads the source tree (files::data_dir), so a missing file fails here. The Python
# module's package, python3-impasto_*.deb beside it, is unpacked over the same root.
set -euo pipefail
deb="$(realpath "${1:?usage: smoke-test.sh IMPASTO.deb [IMPASTO-PIGMENTS-OKUMURA.deb]}")"
addon="${2:+$(realpath "$2")}"
root="$(mktemp -d)"
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root/unpacked"
python_deb="$(ls "$(dirname "$deb")"/python3-impasto_*.deb 2>/dev/null | head -1)"
[ -n "$python_deb" ] || { echo "smoke test: no python3-impasto package beside $deb" >&2; exit 1; }
if dpkg-deb -c "$deb" | grep -q "dist-packages"; then
  echo "smoke test: the impasto package holds the Python module (python3-impasto's)" >&2
  exit 1
fi
dpkg-deb -f "$python_deb" Depends | grep -q "impasto (= $(dpkg-deb -f "$deb" Version))" ||
  { echo "smoke test: python3-impasto does not depend on this impasto" >&2; exit 1; }
dpkg-deb -x "$python_deb" "$root/unpacked"
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

# The Python module, from the unpacked root: it finds the data beside it
# (lib/python3/dist-packages/../../../share/impasto) and reads the painting just saved.
module_dir="$root/unpacked/usr/lib/python3/dist-packages"
compgen -G "$module_dir/impasto*.so" >/dev/null ||
  { echo "smoke test: python3-impasto lacks the Python module" >&2; exit 1; }
PYTHONPATH="$module_dir" /usr/bin/python3 -c "
import impasto
p = impasto.Painting.load('demo.impasto')
assert p.render().shape == (768, 1024, 3) and 'White' in impasto.pigments()" ||
  { echo "smoke test: the Python module cannot read the demo" >&2; exit 1; }

# Only freely licensed data in the main package: no pigment or data file under a
# non-commercial licence, and no pattern of a non-commercial stanza of its copyright file
# names an installed file (the source's data/ is installed as share/impasto/).
if grep -rlE "NonCommercial|BY-NC" "$root/unpacked/usr/share/impasto"; then
  echo "smoke test: the package holds the files above, under a non-commercial licence" >&2
  exit 1
fi
awk '/^Files:/ {files=$0} /^License: .*NC/ {print files}' \
  "$root/unpacked/usr/share/doc/impasto/copyright" | sed 's/^Files://' | tr ' ' '\n' |
  while read -r pattern; do
    [ -n "$pattern" ] || continue
    case "$pattern" in data/*) ;; *) continue ;; esac  # only data/ is installed
    for installed in "$root/unpacked/usr/share/impasto/"${pattern#data/}; do
      if [ -e "$installed" ]; then
        echo "smoke test: $pattern (non-commercial) is in the package" >&2
        exit 1
      fi
    done
  done
"$impasto" pigments list | grep -q "Blue Green Shade .*bundled *CC BY 4.0" ||
  { echo "smoke test: pigments list lacks the free set with its licence" >&2; exit 1; }

# The non-commercial add-on, unpacked over the same root: its pigments join the library.
if [ -n "$addon" ]; then
  dpkg-deb -f "$addon" Section | grep -q "^non-free" ||
    { echo "smoke test: the add-on is not in section non-free" >&2; exit 1; }
  dpkg-deb -x "$addon" "$root/unpacked"
  "$impasto" pigments list | grep -q "Titanium White .*add-on *CC BY-NC-SA 4.0" ||
    { echo "smoke test: the add-on's pigments are not in the library" >&2; exit 1; }
  [ "$("$impasto" pigments list | grep -c " add-on ")" -eq 27 ] ||
    { echo "smoke test: the add-on does not hold 27 pigments" >&2; exit 1; }
  echo "smoke test: $(basename "$addon") adds its 27 pigments to the library"
fi
echo "smoke test: $(basename "$deb") and $(basename "$python_deb") run from an unpacked root (replay, render, thumbnail, Python)"
