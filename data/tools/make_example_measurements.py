#!/usr/bin/env python3
"""Writes data/measurements/synthetic_mixtures.csv: reflectances of opaque mixtures of
four of the bundled acrylics computed with the Kubelka-Munk forward model (plus the Saunderson
interface), rounded to 6 decimals. It exercises
`impasto pigments fit`, which should give back the shipped K and S.

    python3 data/tools/make_example_measurements.py data
"""
import csv
import math
import pathlib
import sys

PIGMENTS = ["White", "Blue Green Shade", "Red", "Cold Yellow"]
K1, K2 = 0.03, 0.65


def read_pigment(path):
    with path.open() as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    return {float(r[0]): (float(r[1]), float(r[2])) for r in rows[1:]}


def reflectance(mix, table):
    out = []
    for nm in sorted(table[PIGMENTS[0]]):
        k = sum(c * table[p][nm][0] for p, c in mix.items())
        s = sum(c * table[p][nm][1] for p, c in mix.items())
        q = k / s
        r = 1.0 / (1.0 + q + math.sqrt(q * q + 2.0 * q))
        out.append(K1 + (1 - K1) * (1 - K2) * r / (1 - K2 * r))
    return out


def main():
    data = pathlib.Path(sys.argv[1])
    table = {}
    for f in (data / "pigments").glob("*.csv"):
        name = next(l[len("# name: "):].strip() for l in f.open() if l.startswith("# name: "))
        if name in PIGMENTS:
            table[name] = read_pigment(f)
    samples = {}
    short = {"White": "white", "Blue Green Shade": "blue",
             "Red": "red", "Cold Yellow": "yellow"}
    for p in PIGMENTS:
        samples[f"{short[p]} masstone"] = {p: 1.0}
    for p in PIGMENTS[1:]:
        for white in (0.5, 0.9):
            samples[f"{short[p]} tint {white:g} white"] = {"White": white, p: 1 - white}
    for a, b in (("Blue Green Shade", "Cold Yellow"),
                 ("Red", "Cold Yellow"), ("Blue Green Shade", "Red")):
        samples[f"{short[a]} + {short[b]}"] = {a: 0.5, b: 0.5}
    wavelengths = sorted(table[PIGMENTS[0]])
    columns = {name: reflectance(mix, table) for name, mix in samples.items()}
    out = data / "measurements" / "synthetic_mixtures.csv"
    with out.open("w") as f:
        f.write("# quantity: reflectance\n")
        f.write("# description: synthetic measurements of opaque drawdowns, computed from the shipped "
                "K and S (the free Kimera set) with the Kubelka-Munk model and a Saunderson interface; for trying "
                "'impasto pigments fit'\n")
        f.write("# licence: CC BY 4.0, derived from M. Iwanicki's PaintMixing measurements "
                "(see data/pigments/README.md)\n")
        f.write("# reference: White\n")
        f.write(f"# saunderson: {K1} {K2}\n")
        for name, mix in samples.items():
            f.write(f"# mix {name}: " + "; ".join(f"{p}={c:g}" for p, c in mix.items()) + "\n")
        f.write(",".join(["wavelength_nm"] + list(samples)) + "\n")
        for i, nm in enumerate(wavelengths):
            f.write(",".join([f"{nm:g}"] + [f"{columns[n][i]:.6f}" for n in samples]) + "\n")


if __name__ == "__main__":
    main()
