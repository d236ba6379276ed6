"""Paint a procedural field of strokes: short dabs of a flat brush on a grid, each turned along
a swirl and loaded with one of three paints, then render it under a low light.
Usage: python3 stroke_field.py OUT_FOLDER"""
import math
import os
import sys

import numpy as np

import impasto

out = sys.argv[1]
p = impasto.Painting(600, 400, dpi=200)  # 76 x 51 mm
p.set_brush("flat", size_mm=4.0, stiffness=0.6)
paints = ["Blue Green Shade", "Warm Yellow", "White"]
for row in range(6):
    for column in range(9):
        cx, cy = 8.0 + 7.5 * column, 7.0 + 7.5 * row
        angle = math.atan2(cy - 25.0, cx - 38.0) + math.pi / 2  # around the centre
        p.wipe_brush()
        p.load_brush({paints[(row + column) % 3]: 1.0}, 12.0, body="heavy")
        t = np.linspace(-3.0, 3.0, 25)
        pressure = np.sin(np.linspace(0.15, math.pi - 0.15, 25)) * 0.8
        p.stroke(np.column_stack([cx + t * math.cos(angle), cy + t * math.sin(angle), pressure]))
p.render_to(os.path.join(out, "stroke_field.png"), light_dir=(225.0, 30.0))
print(f"{len(p.pigments)} paints, {p.totals()['canvas']['volume_mm3']:.1f} mm^3 on the canvas, "
      f"highest {p.heights().max():.2f} mm")
