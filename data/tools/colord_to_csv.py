#!/usr/bin/env python3
"""Converts Debian colord-data's CIE tables (CGATS .cmf/.sp files) to Impasto's spectral CSV.

Run once by a maintainer (needs the colord-data package); the program itself only reads the
CSVs this writes into data/spectra/, so colord is not needed at run time.

    python3 data/tools/colord_to_csv.py /usr/share/colord data/spectra
"""
import pathlib
import sys


def read_cgats(path):
    """Returns (keywords, wavelengths_nm, rows of values) of one colord CGATS file."""
    keywords, fields, rows = {}, [], []
    section = "header"
    for line in path.read_text().splitlines():
        stripped = line.strip()
        if stripped == "BEGIN_DATA_FORMAT":
            section = "format"
        elif stripped == "END_DATA_FORMAT":
            section = "header"
        elif stripped == "BEGIN_DATA":
            section = "data"
        elif stripped == "END_DATA":
            section = "header"
        elif section == "format":
            fields += stripped.split()
        elif section == "data":
            rows.append([float(v) for v in stripped.split()])
        elif "\t" in stripped:
            key, value = stripped.split("\t", 1)
            keywords[key] = value.strip().strip('"')
    start = float(keywords["SPECTRAL_START_NM"])
    end = float(keywords["SPECTRAL_END_NM"])
    bands = int(keywords["SPECTRAL_BANDS"])
    step = (end - start) / (bands - 1)
    wavelengths = [start + i * step for i in range(bands)]
    for row in rows:
        if len(row) != bands:
            sys.exit(f"{path}: a data row has {len(row)} values, expected {bands}")
    return keywords, wavelengths, rows


def number(value):
    return f"{value:.10g}"


def write_csv(path, metadata, names, wavelengths, columns):
    with path.open("w") as out:
        for key, value in metadata:
            out.write(f"# {key}: {value}\n")
        out.write(",".join(["wavelength_nm"] + names) + "\n")
        for i, nm in enumerate(wavelengths):
            out.write(",".join([number(nm)] + [number(c[i]) for c in columns]) + "\n")


def main():
    colord, target = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    source = "Debian package colord-data 1.4.6 (/usr/share/colord), converted by data/tools/colord_to_csv.py"

    cmf = colord / "cmf" / "CIE1931-2deg-XYZ.cmf"
    _, wavelengths, rows = read_cgats(cmf)
    write_csv(target / "cie1931_2deg.csv",
              [("quantity", "cmf"), ("units", "dimensionless, y_bar = 1 at 555 nm"),
               ("description", "CIE 1931 2 degree standard observer colour-matching functions"),
               ("source", f"{source}: cmf/{cmf.name}")],
              ["x_bar", "y_bar", "z_bar"], wavelengths, rows)

    for sp in sorted((colord / "illuminant").glob("CIE-*.sp")):
        name = sp.stem.removeprefix("CIE-")
        _, wavelengths, rows = read_cgats(sp)
        write_csv(target / "illuminants" / f"{name}.csv",
                  [("quantity", "spectral_power"), ("units", "relative"),
                   ("description", f"CIE standard illuminant {name}"),
                   ("source", f"{source}: illuminant/{sp.name}")],
                  [name], wavelengths, rows)


if __name__ == "__main__":
    main()
