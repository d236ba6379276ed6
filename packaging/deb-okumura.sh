#!/usr/bin/env bash
# Builds the optional, non-commercial pigment add-on beside the main package:
# build/release/package/impasto-pigments-okumura_VERSION_all.deb. It installs the 27 Golden
# pigments (CC BY-NC-SA 4.0) into /usr/share/impasto/pigment-addons/okumura/, a folder the
# pigment library layers after the bundled set. The main package holds none of them.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/release/package}"
version="$(sed -n 's/^project(impasto VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)"
name=impasto-pigments-okumura
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
root="$stage/$name"
install -d "$root/DEBIAN" "$root/usr/share/impasto/pigment-addons/okumura" \
  "$root/usr/share/doc/$name"
install -m 644 packaging/pigments-okumura/*.csv "$root/usr/share/impasto/pigment-addons/okumura/"
install -m 644 packaging/pigments-okumura/README.md "$root/usr/share/doc/$name/README.md"
install -m 644 packaging/pigments-okumura/copyright "$root/usr/share/doc/$name/copyright"
size="$(du -sk "$root/usr" | cut -f1)"
cat >"$root/DEBIAN/control" <<CONTROL
Package: $name
Version: $version
Architecture: all
Section: non-free/graphics
Priority: optional
Depends: impasto (>= $version)
Installed-Size: $size
Maintainer: Impasto maintainers <maintainers@impasto.invalid>
Description: Golden acrylic pigments for Impasto (non-commercial licence)
 Kubelka-Munk K and S of 27 Golden Matte Fluid Acrylics, measured by
 Y. Okumura (RIT Munsell Color Science Laboratory, 2005), for Impasto's
 pigment library. Licensed CC BY-NC-SA 4.0: no commercial use.
CONTROL
mkdir -p "$out"
dpkg-deb --root-owner-group --build "$root" "$out/${name}_${version}_all.deb" >/dev/null
ls "$out/${name}_${version}_all.deb"
