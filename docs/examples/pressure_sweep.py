"""Sweep a parameter and measure the marks: the same stroke of a round brush at pressures from
0.2 to 1.0, each on a fresh canvas; the paint laid and how thick it stands, as a table (CSV on
standard output, plottable with any tool). Usage: python3 pressure_sweep.py OUT_FOLDER"""
import os
import sys

import numpy as np

import impasto

out = sys.argv[1]
rows = ["pressure,laid_mm3,median_thickness_mm,width_mm"]
for pressure in (0.2, 0.4, 0.6, 0.8, 1.0):
    p = impasto.Painting(300, 100, dpi=254)  # 0.1 mm cells
    p.set_brush("round", size_mm=4.0, stiffness=0.5)
    p.load_brush({"Red": 1.0}, 60.0)
    x = np.linspace(3.0, 27.0, 97)
    p.stroke(np.column_stack([x, np.full_like(x, 5.0), np.full_like(x, pressure)]))
    wet = p.wet()
    painted = wet[wet > 0.01]
    width = (wet[:, 150] > 0.01).sum() * p.cell_mm
    laid = p.totals()["canvas"]["volume_mm3"]
    rows.append(f"{pressure:.1f},{laid:.2f},{np.median(painted):.3f},{width:.2f}")
print("\n".join(rows))
with open(os.path.join(out, "pressure_sweep.csv"), "w") as f:
    f.write("\n".join(rows) + "\n")
