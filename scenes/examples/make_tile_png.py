#!/usr/bin/env python3
"""Writes tile.png, the 4x4 8-bit sRGB texture all-features.json uses (a two-tone tile with a
dark border), with the standard library only: python3 make_tile_png.py"""
import pathlib
import struct
import zlib


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(v for px in row for v in px) for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


dark, light, warm = (60, 50, 40), (200, 190, 170), (180, 120, 80)
rows = [[dark if x in (0, 3) or y in (0, 3) else (light if (x + y) % 2 else warm) for x in range(4)] for y in range(4)]
pathlib.Path(__file__).with_name("tile.png").write_bytes(png(4, 4, rows))
