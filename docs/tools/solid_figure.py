#!/usr/bin/env python3
"""Draws docs/images/export-solid.png from a PLY that `impasto export --ply` wrote: the solid
seen from the front and above, lit from the upper left (each triangle flat-shaded in its
vertices' colours, drawn back to front), and beside it a part of the top seen from above with
the triangles' edges, where flat areas take few triangles.

    impasto export demo.impasto --ply demo.ply --relief-scale 3
    python3 docs/tools/solid_figure.py demo.ply docs/images/export-solid.png
"""
import struct
import sys

import numpy as np
from PIL import Image, ImageDraw


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    vertices = int(next(l.split()[2] for l in header if l.startswith("element vertex")))
    faces = int(next(l.split()[2] for l in header if l.startswith("element face")))
    v = np.frombuffer(data, dtype=np.dtype([("p", "<f4", 3), ("c", "u1", 3)]), count=vertices,
                      offset=end)
    f = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]), count=faces,
                      offset=end + vertices * 15)
    return v["p"].astype(np.float64), v["c"].astype(np.float64), f["i"]


def oblique(points, colours, triangles, width):
    tilt = np.radians(55.0)  # the view's angle from the canvas
    x = points[:, 0]
    y = points[:, 1] * np.sin(tilt) + points[:, 2] * np.cos(tilt)
    depth = points[:, 1] * np.cos(tilt) - points[:, 2] * np.sin(tilt)
    scale = (width - 20) / (x.max() - x.min())
    height = int((y.max() - y.min()) * scale) + 20
    sx = 10 + (x - x.min()) * scale
    sy = height - 10 - (y - y.min()) * scale
    a, b, c = (points[triangles[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True) + 1e-12
    light = np.array([-0.5, 0.6, 0.62])
    light /= np.linalg.norm(light)
    shade = 0.25 + 0.75 * np.clip(normal @ light, 0.0, 1.0)
    colour = colours[triangles].mean(axis=1) * shade[:, None]
    image = Image.new("RGB", (width, height), (40, 40, 44))
    draw = ImageDraw.Draw(image)
    toward_viewer = np.array([0.0, -np.cos(tilt), np.sin(tilt)])
    facing = normal @ toward_viewer > 0.0  # the back and the far sides are hidden
    for t in np.argsort(-depth[triangles].mean(axis=1)):  # far first
        if not facing[t]:
            continue
        i = triangles[t]
        draw.polygon([(sx[k], sy[k]) for k in i], fill=tuple(int(v) for v in colour[t]))
    return image


def edges_from_above(points, colours, triangles, box, size):
    x0, y0, x1, y1 = box
    inside = np.all((points[triangles][:, :, 0] >= x0) & (points[triangles][:, :, 0] <= x1) &
                    (points[triangles][:, :, 1] >= y0) & (points[triangles][:, :, 1] <= y1) &
                    (points[triangles][:, :, 2] > -0.01), axis=1)
    scale = size / (x1 - x0)
    image = Image.new("RGB", (size, int((y1 - y0) * scale)), (255, 255, 255))
    draw = ImageDraw.Draw(image)
    for t in np.nonzero(inside)[0]:
        i = triangles[t]
        corners = [((points[k, 0] - x0) * scale, (y1 - points[k, 1]) * scale) for k in i]
        draw.polygon(corners, fill=tuple(int(v) for v in colours[i].mean(axis=0)),
                     outline=(20, 20, 20))
    return image


def main():
    points, colours, triangles = read_ply(sys.argv[1])
    left = oblique(points, colours, triangles, 900)
    w, h = points[:, 0].max(), points[:, 1].max()
    right = edges_from_above(points, colours, triangles, (0.45 * w, 0.45 * h, 0.62 * w, 0.6 * h),
                             left.height)
    figure = Image.new("RGB", (left.width + right.width + 10, left.height), (255, 255, 255))
    figure.paste(left, (0, 0))
    figure.paste(right, (left.width + 10, 0))
    figure.save(sys.argv[2], optimize=True)


if __name__ == "__main__":
    main()
