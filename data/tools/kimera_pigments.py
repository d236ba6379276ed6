#!/usr/bin/env python3
"""Builds Impasto's free default pigment set from the Kimera acrylic measurements
(M. Iwanicki, github.com/miciwan/PaintMixing, data/masstone.json and data/mix1.json, CC BY 4.0).

    python3 data/tools/kimera_pigments.py KIMERA_DIR IMPASTO_BINARY OUT_FOLDER
    python3 data/tools/kimera_pigments.py --report KIMERA_DIR IMPASTO_BINARY   # the repeats' spread

1. Writes data/measurements/kimera_acrylics.csv: each paint's masstone and its tint with
   white, the three repeats averaged, as fractions (the source is in percent), resampled to
   Impasto's 10 nm grid by averaging the channels within 5 nm of each node (about four of
   the source's 2.3 nm channels), 380-720 nm. Outside 381-720 nm nothing was measured: the
   reflectance at 380 nm is held down to 360 nm and the one at 720 nm up to 750 nm, so K
   and S there are those of the ends.
2. Fits K and S with `impasto pigments fit` (White's S fixed to 1, the Saunderson interface
   the renderer uses, with the share of k1 the instrument read: SURFACE_SEEN below).
3. Fits each repeat alone the same way and writes the spread of K and S between them (the
   median over 400-700 nm of their standard deviation over their mean) into each file as its
   stated uncertainty, with the maker, the source and the licence.

The tints are weighed (mass ratios); Impasto mixes by volume. The data gives no densities, so
the ratios are used as given: a fitted K or S is per unit mass of paint.
"""
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile

GRID = list(range(360, 751, 10))
MEASURED = (380, 720)
# The darkest reading of the set is 2.2 % (Blue Green Shade near 600 nm), below the 3 % k1
# of a paint surface: the instrument read only part of the surface's reflection. 0.6 of it
# (1.8 %) leaves every reading above it.
K1, K2, SURFACE_SEEN = 0.03, 0.65, 0.6
SOURCE = ("M. Iwanicki, PaintMixing (github.com/miciwan/PaintMixing, data/masstone.json and "
          "data/mix1.json, commit e496fd46b150c20bfeafea518a84818853988093)")
LICENCE = "CC BY 4.0 (credit: " + SOURCE + ")"


def title(name):
    return " ".join(word.capitalize() for word in name.split())


def resampled(wavelengths, percent):
    """Box-average channels within 5 nm of each node; hold the measured ends outside them."""
    node = {}
    for nm in range(MEASURED[0], MEASURED[1] + 1, 10):
        inside = [p for w, p in zip(wavelengths, percent) if abs(w - nm) <= 5.0]
        node[nm] = sum(inside) / len(inside) / 100.0
    return [node[min(max(nm, MEASURED[0]), MEASURED[1])] for nm in GRID]


def samples(kimera):
    """name -> list of (components, reflectance on GRID), one per repeat, masstones and tints."""
    out = {}
    for file in ("masstone.json", "mix1.json"):
        records = json.loads((kimera / file).read_text())
        wavelengths = records[0]["values"]
        for record in records[1:]:
            if record["type"] == "masstone":
                key, mix = title(record["name"]), {title(record["name"]): 1.0}
            else:
                parts = {title(p): v for p, v in record["components"].items()}
                total = sum(parts.values())
                paint = next(p for p in parts if p != "White")
                key, mix = paint + " tint", {p: v / total for p, v in parts.items()}
            out.setdefault(key, []).append((mix, resampled(wavelengths, record["reflectance"])))
    return out


def write_measurements(path, table, repeat, description):
    names = sorted(table, key=lambda n: (n != "White", n))
    lines = ["# quantity: reflectance",
             "# description: " + description,
             "# source: " + SOURCE,
             "# licence: " + LICENCE,
             "# reference: White",
             f"# saunderson: {K1} {K2}",
             f"# surface_seen: {SURFACE_SEEN}"]
    for name in names:
        mix = table[name][0][0]
        lines.append(f"# mix {name}: " + "; ".join(f"{p}={c:.4f}" for p, c in mix.items()))
    lines.append("wavelength_nm," + ",".join(names))
    for i, nm in enumerate(GRID):
        if repeat is None:
            values = [statistics.fmean(r[1][i] for r in table[n]) for n in names]
        else:
            values = [table[n][repeat][1][i] for n in names]
        lines.append(f"{nm}," + ",".join(f"{v:.6f}" for v in values))
    path.write_text("\n".join(lines) + "\n")


def fit(impasto, measurements, out):
    subprocess.run([impasto, "pigments", "fit", str(measurements), "--out", str(out), "--force"],
                   check=True, stdout=subprocess.DEVNULL)


def read_ks(path):
    rows = [l.split(",") for l in path.read_text().splitlines()
            if l and not l.startswith("#") and not l.startswith("wavelength")]
    return {float(r[0]): (float(r[1]), float(r[2])) for r in rows}


def spread(repeats, column):
    shares = []
    for nm in range(400, 701, 10):
        values = [r[nm][column] for r in repeats]
        mean = statistics.fmean(values)
        if mean > 0:
            shares.append(statistics.stdev(values) / mean)
    return 100.0 * statistics.median(shares)


def ciede2000(lab1, lab2):
    """CIEDE2000 (Sharma, Wu and Dalal 2005), kL = kC = kH = 1."""
    from math import atan2, cos, degrees, exp, hypot, radians, sin, sqrt
    (l1, a1, b1), (l2, a2, b2) = lab1, lab2
    c_bar = (hypot(a1, b1) + hypot(a2, b2)) / 2
    g = 0.5 * (1 - sqrt(c_bar ** 7 / (c_bar ** 7 + 25 ** 7)))
    a1p, a2p = (1 + g) * a1, (1 + g) * a2
    c1p, c2p = hypot(a1p, b1), hypot(a2p, b2)
    h1p = degrees(atan2(b1, a1p)) % 360 if c1p else 0.0
    h2p = degrees(atan2(b2, a2p)) % 360 if c2p else 0.0
    dl, dc = l2 - l1, c2p - c1p
    dh = 0.0
    if c1p * c2p:
        dh = h2p - h1p
        dh = dh - 360 if dh > 180 else dh + 360 if dh < -180 else dh
    dhh = 2 * sqrt(c1p * c2p) * sin(radians(dh / 2))
    l_bar, cp_bar = (l1 + l2) / 2, (c1p + c2p) / 2
    if c1p * c2p == 0:
        h_bar = h1p + h2p
    elif abs(h1p - h2p) <= 180:
        h_bar = (h1p + h2p) / 2
    else:
        h_bar = (h1p + h2p + 360) / 2 if h1p + h2p < 360 else (h1p + h2p - 360) / 2
    t = (1 - 0.17 * cos(radians(h_bar - 30)) + 0.24 * cos(radians(2 * h_bar))
         + 0.32 * cos(radians(3 * h_bar + 6)) - 0.20 * cos(radians(4 * h_bar - 63)))
    sl = 1 + 0.015 * (l_bar - 50) ** 2 / sqrt(20 + (l_bar - 50) ** 2)
    sc, sh = 1 + 0.045 * cp_bar, 1 + 0.015 * cp_bar * t
    rt = (-2 * sqrt(cp_bar ** 7 / (cp_bar ** 7 + 25 ** 7))
          * sin(radians(60 * exp(-(((h_bar - 275) / 25) ** 2)))))
    return sqrt((dl / sl) ** 2 + (dc / sc) ** 2 + (dhh / sh) ** 2 + rt * (dc / sc) * (dhh / sh))


def lab_of_columns(impasto, path):
    """L*a*b* under D65 of each column of a reflectance CSV, by `impasto color xyz`."""
    out = subprocess.run([impasto, "color", "xyz", str(path), "--light", "D65", "--json"],
                         check=True, capture_output=True, text=True).stdout
    report = json.loads(out)
    return [tuple(sample["Lab"]) for sample in report["samples"]]


def report(impasto, table, folder):
    """A markdown table of how far each repeat lies from the average the paints were fitted to:
    the largest CIEDE2000 (D65) and reflectance RMS of the three."""
    average = folder / "average.csv"
    write_measurements(average, table, None, "average")
    repeats = []
    for i in range(3):
        path = folder / f"spread{i}.csv"
        write_measurements(path, table, i, f"repeat {i + 1}")
        repeats.append(lab_of_columns(impasto, path))
    mean = lab_of_columns(impasto, average)
    names = sorted(table, key=lambda n: (n != "White", n))
    print("| paint | masstone: dE00 / RMS R | tint: dE00 / RMS R |")
    print("|---|---|---|")
    rows = {}
    for c, name in enumerate(names):
        de = max(ciede2000(mean[c], r[c]) for r in repeats)
        measured = [r[1] for r in table[name]]
        average_r = [statistics.fmean(m[i] for m in measured) for i in range(len(GRID))]
        rms = max(sqrt_mean_square([m[i] - average_r[i] for i in range(len(GRID))])
                  for m in measured)
        paint = name[:-len(" tint")] if name.endswith(" tint") else name
        rows.setdefault(paint, {})["tint" if name.endswith(" tint") else "masstone"] = (de, rms)
    for paint, r in rows.items():
        cells = [f"{r[k][0]:.2f} / {r[k][1]:.4f}" if k in r else "-" for k in ("masstone", "tint")]
        print(f"| {paint} | {cells[0]} | {cells[1]} |")


def sqrt_mean_square(values):
    return (sum(v * v for v in values) / len(values)) ** 0.5


def main():
    if sys.argv[1:2] == ["--report"]:
        kimera, impasto = pathlib.Path(sys.argv[2]), sys.argv[3]
        with tempfile.TemporaryDirectory() as tmp:
            report(impasto, samples(kimera), pathlib.Path(tmp))
        return
    kimera, impasto, out = (pathlib.Path(a) for a in sys.argv[1:4])
    table = samples(kimera)
    repo = pathlib.Path(__file__).resolve().parents[2]
    measurements = repo / "data" / "measurements" / "kimera_acrylics.csv"
    write_measurements(measurements, table, None,
                       "Kimera Kolors acrylics, masstones and tints with white (mass ratios), "
                       "three repeats averaged, percent as fractions, 10 nm boxes, ends held "
                       "from 380 and 720 nm (data/tools/kimera_pigments.py)")
    out.mkdir(parents=True, exist_ok=True)
    fit(impasto, measurements, out)
    with tempfile.TemporaryDirectory() as tmp:
        repeats = []
        for i in range(3):
            folder = pathlib.Path(tmp) / f"repeat{i}"
            path = pathlib.Path(tmp) / f"repeat{i}.csv"
            write_measurements(path, table, i, f"repeat {i + 1} of 3")
            fit(impasto, path, folder)
            repeats.append(folder)
        for file in sorted(out.glob("*.csv")):
            fits = [read_ks(folder / file.name) for folder in repeats]
            k, s = spread(fits, 0), spread(fits, 1)
            head, body = [], []
            for line in file.read_text().splitlines():
                if line.startswith("#"):
                    head.append(line)
                elif line.startswith("wavelength"):
                    body.append(line)
                else:  # six significant digits, as the measurements hold
                    nm, k_value, s_value = line.split(",")
                    body.append(f"{nm},{float(k_value):.6g},{float(s_value):.6g}")
            written_here = ("# source:", "# licence:", "# fitted_from:", "# binder:", "# product:",
                            "# uncertainty:", "# colour_index:")
            head = [l for l in head if not l.startswith(written_here)]
            head += ["# binder: acrylic",
                     "# product: Kimera Kolors acrylic (the maker's name for the paint)",
                     "# source: " + SOURCE + "; fitted by data/tools/kimera_pigments.py from "
                     "data/measurements/kimera_acrylics.csv",
                     "# licence: CC BY 4.0",
                     f"# uncertainty: K {k:.1f} %, S {s:.1f} % (the spread of three repeats' fits, "
                     "median over 400-700 nm of their standard deviation over their mean)"]
            file.write_text("\n".join(head + body) + "\n")


if __name__ == "__main__":
    main()
