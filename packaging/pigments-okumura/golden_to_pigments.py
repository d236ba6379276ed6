#!/usr/bin/env python3
"""Converts the Golden Matte Fluid Acrylics K/S table (wide CSV: one row per pigment and
quantity, columns 360nm..750nm) into one Impasto pigment file per pigment.

    python3 packaging/pigments-okumura/golden_to_pigments.py \
        ../shared/data/pigments/golden_matte_fluid_acrylics_KS.csv packaging/pigments-okumura
"""
import csv
import pathlib
import re
import sys


def file_name(pigment):
    """The same rule as impasto::data::pigment_file_name."""
    slug = re.sub(r"[^a-z0-9]+", "_", pigment.lower()).strip("_")
    return (slug or "pigment") + ".csv"


def main():
    source, target = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    with source.open(newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    wavelengths = [h.removesuffix("nm") for h in header[2:]]
    table = {}
    for row in rows:
        table.setdefault(row[0], {})[row[1]] = row[2:]
    for pigment, quantities in table.items():
        with (target / file_name(pigment)).open("w") as out:
            out.write("# quantity: kubelka_munk\n")
            out.write(f"# name: {pigment}\n")
            out.write("# binder: acrylic\n")
            out.write("# product: Golden Matte Fluid Acrylics\n")
            out.write("# units: K and S per unit film thickness, S relative (Titanium White S = 1)\n")
            out.write("# interface: corrected for the paint-air interface (Saunderson k1 0.03, k2 0.65)\n")
            out.write("# source: Y. Okumura, M.S. thesis, RIT Munsell Color Science Laboratory, 2005;"
                      " tabulated in rubenwiersma/painting_tools\n")
            out.write("# licence: CC BY-NC-SA 4.0, non-commercial use only (see README.md, LICENSE)\n")
            out.write("wavelength_nm,K,S\n")
            for i, nm in enumerate(wavelengths):
                out.write(f"{nm},{quantities['K'][i]},{quantities['S'][i]}\n")


if __name__ == "__main__":
    main()
