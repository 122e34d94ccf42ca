#!/usr/bin/env python3
"""Writes the billiard-ball textures of pool-balls.json into scenes/textures/: equirectangular
8-bit sRGB PNGs in pdrt's sphere mapping (docs/scene-format.md: +y is the pole, u the azimuth
from +x toward +z, the image's top row the +y pole), a coloured ball or a white ball with a
coloured stripe, with a white number disc centred on the equator at u = 0.5, facing -x in the
ball's object space. Pure Python (zlib) so the images are the same bytes wherever they are
made: python3 scenes/make_ball_textures.py"""
import math
import os
import struct
import zlib

W, H = 512, 256
DISC = math.radians(24)   # angular radius of the number disc
STRIPE = math.radians(32) # half-width of a stripe ball's band, in latitude

# 5x7 bitmap digits, one string per row, '#' = ink.
FONT = {
    "1": ["..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."],
    "4": ["...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."],
    "8": [".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."],
    "9": [".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."],
}

BALLS = {  # name: (colour in sRGB 0-255, stripe?, number)
    "ball-1": ((236, 178, 22), False, "1"),
    "ball-4": ((92, 28, 120), False, "4"),
    "ball-8": ((18, 18, 18), False, "8"),
    "ball-9": ((236, 178, 22), True, "9"),
}
WHITE, INK = (240, 236, 222), (16, 16, 16)


def direction(u, v):
    phi, theta = 2 * math.pi * u, math.pi * v
    return (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))


def texel(colour, stripe, number, u, v):
    d = direction(u, v)
    c = direction(0.5, 0.5)  # disc centre on the equator
    cos_a = sum(a * b for a, b in zip(d, c))
    if cos_a > math.cos(DISC):
        # Gnomonic projection onto the plane tangent at the disc centre (direction -x): x toward
        # +z, which is the viewer's right seen from outside, y toward the top pole, both in units
        # of the disc's radius. (u grows toward -z there, so the glyphs are mirrored in the image.)
        east = (0.0, 0.0, 1.0)
        up = (0.0, 1.0, 0.0)
        x = sum(a * b for a, b in zip(d, east)) / cos_a / math.tan(DISC)
        y = sum(a * b for a, b in zip(d, up)) / cos_a / math.tan(DISC)
        glyphs = [FONT[ch] for ch in number]
        gw = 6 * len(glyphs) - 1  # 5 columns per digit, 1 between
        scale = 0.16              # disc radii per font cell
        col = math.floor((x / scale) + gw / 2)
        row = math.floor((-y / scale) + 3.5)
        if 0 <= row < 7 and 0 <= col < gw and col % 6 < 5 and glyphs[col // 6][row][col % 6] == "#":
            return INK
        return WHITE
    if stripe:
        latitude = math.pi / 2 - math.pi * v
        return colour if abs(latitude) < STRIPE else WHITE
    return colour


def png(path, rows):
    raw = b"".join(b"\0" + bytes(v for px in row for v in px) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


out_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "textures")
os.makedirs(out_dir, exist_ok=True)
for name, (colour, stripe, number) in BALLS.items():
    rows = [[texel(colour, stripe, number, (i + 0.5) / W, (j + 0.5) / H) for i in range(W)] for j in range(H)]
    png(os.path.join(out_dir, name + ".png"), rows)
