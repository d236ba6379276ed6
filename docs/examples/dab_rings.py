"""Short dabs and what their ends leave: three 6 mm dabs of a 10 mm round in paste, each
eased off over its last 2 mm as a pen does (or released at once as a mouse does, with
--released), rendered under a low light to OUT_FOLDER/dabs.png; and how much each dab's paint
ripples along its middle over its travel (the RMS of the height less its 1 mm moving average,
as a share of the film), which concentric rings where the contact stopped would raise.
Usage: python3 dab_rings.py OUT_FOLDER [--released] [NAME=VALUE ...] (paint model constants)"""
import os
import sys

import numpy as np

import impasto

out = sys.argv[1]
released = "--released" in sys.argv[2:]
params = dict(a.split("=") for a in sys.argv[2:] if "=" in a)
p = impasto.Painting(600, 260, dpi=254, seed=1)  # 0.1 mm cells, woven
if params:
    p.params = {name: float(value) for name, value in params.items()}
p.set_brush("round", size_mm=10.0)
p.load_brush({"White": 3, "Red": 1}, 250.0, body="paste")
starts = (10.0, 28.0, 46.0)
for x0 in starts:
    samples = 30
    points = []
    for k in range(samples + 1):
        eased = 0.7 * min(1.0, (samples - k) / 10)
        pressure = (0.7 if k < samples else 0.0) if released else eased
        points.append((x0 + 6.0 * k / samples, 13.0, pressure, 0.012 * k))
    p.stroke(points)
p.render_to(os.path.join(out, "dabs.png"), light_dir=(225, 25))
heights = p.heights()
film = np.median(heights[heights > 0.05])
middle = heights[120:140].mean(axis=0)  # 2 mm across the dabs' middle: furrows average out
ripples = []
for x0 in starts:
    profile = middle[int((x0 + 0.5) * 10) : int((x0 + 6.5) * 10)]
    smooth = np.convolve(profile, np.ones(10) / 10, mode="same")
    rest = (profile - smooth)[10:-10]
    ripples.append(np.sqrt((rest**2).mean()) / film)
print("ripple % of the film: " + " ".join(f"{100 * r:.2f}" for r in ripples))
