#!/usr/bin/env python3
"""Writes scenes/comb.json: Cook (1986) Fig. 12, a comb of 200 triangular slivers 1.01
pixels apart. The camera maps the plane z = 0 to the film at exactly 1 unit per pixel, so
regular sampling turns the comb into a low-frequency moire while jitter and Poisson-disk
sampling turn it into noise."""
import json
import math
import os

W, H = 256, 64
dist = 100.0
vfov = 2 * math.degrees(math.atan((H / 2) / dist))  # half-height H/2 units at distance 100
verts, idx = [], []
for i in range(200):
    x = -100.5 + 1.01 * i
    b = len(verts)
    verts += [[round(x - 0.25, 4), -28, 0], [round(x + 0.25, 4), -28, 0], [round(x, 4), 28, 0]]
    idx += [b, b + 1, b + 2]
scene = {
    "camera": {"position": [0, 0, dist], "look_at": [0, 0, 0], "vfov_deg": round(vfov, 6)},
    "film": {"width": W, "height": H, "filter": {"type": "box", "radius": 0.5}},
    "sampler": {"type": "poisson", "spp": 16, "seed": 1},
    "integrator": {"max_depth": 1},
    "materials": {"white": {"type": "emitter", "radiance": [1, 1, 1]}},
    "objects": [{"type": "mesh", "material": "white", "vertices": verts, "indices": idx}],
}
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "comb.json")
with open(out, "w") as f:
    json.dump(scene, f, separators=(",", ":"))
    f.write("\n")
print("wrote", out)
