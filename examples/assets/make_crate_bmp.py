#!/usr/bin/env python3
"""Writes crate.bmp: a 64x64, 24-bit wooden crate texture for the examples (drawn here,
procedurally, so the repository owns it). Run from this folder: python3 make_crate_bmp.py"""
import struct

W = H = 64


def hash2(x, y):
    h = (x * 374761393 + y * 668265263) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return (h ^ (h >> 16)) & 0xFF


def texel(x, y):
    frame = x < 6 or y < 6 or x >= W - 6 or y >= H - 6
    diagonal = abs(x - y) < 5
    plank = (y // 13) % 2
    grain = hash2(x // 3, y) // 16 + (x * 7 + y // 2) % 11
    if frame or diagonal:
        r, g, b = 150 + grain, 92 + grain // 2, 40
        if x in (6, W - 7) or y in (6, H - 7) or abs(x - y) == 4:
            r, g, b = 70, 40, 20  # dark edge lines
    else:
        r, g, b = 190 + grain - 20 * plank, 130 + grain // 2 - 14 * plank, 66
        if y % 13 == 0:
            r, g, b = 96, 58, 28  # gaps between planks
    nail = (x - 3) % 58 == 0 and (y - 3) % 58 == 0
    if nail:
        r, g, b = 200, 200, 210
    return min(r, 255), min(g, 255), min(b, 255)


rows = []
for y in reversed(range(H)):  # BMP rows go bottom-up
    row = b"".join(struct.pack("BBB", *reversed(texel(x, y))) for x in range(W))
    rows.append(row)
pixels = b"".join(rows)
header = struct.pack("<2sIHHI", b"BM", 54 + len(pixels), 0, 0, 54)
info = struct.pack("<IiiHHIIiiII", 40, W, H, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
with open("crate.bmp", "wb") as f:
    f.write(header + info + pixels)
