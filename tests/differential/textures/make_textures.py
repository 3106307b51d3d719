#!/usr/bin/env python3
# Writes the textured differential corpus's 8-bit PNGs (toon_ramp, bumps, albedo_srgb); kept so they can be remade.
import math
import struct
import zlib


def write_png(path, width, height, pixel):
    rows = b"".join(b"\0" + bytes(v for x in range(width) for v in pixel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 9)))
        f.write(chunk(b"IEND", b""))


def byte(v):
    return max(0, min(255, round(v * 255)))


# A toon ramp indexed by N·L along u: three warm-to-cool bands with soft 4-texel edges,
# coloured so that swapping channels changes every band.
def ramp(x, y):
    t = (x + 0.5) / 64
    bands = [(0.0, (0.10, 0.12, 0.35)), (0.35, (0.45, 0.30, 0.55)), (0.7, (0.95, 0.75, 0.40))]
    colour = bands[0][1]
    for edge, c in bands[1:]:
        w = min(1.0, max(0.0, (t - edge) * 16 + 0.5))
        colour = tuple(a + (b - a) * w for a, b in zip(colour, c))
    return tuple(byte(v) for v in colour)


# A tangent-space normal map: a grid of round bumps, stronger in v than in u so a flipped v moves every bump.
def bumps(x, y):
    u, v = (x + 0.5) / 64, (y + 0.5) / 64
    du = 0.35 * math.cos(2 * math.pi * 4 * u) * math.sin(math.pi * v)
    dv = 0.6 * math.sin(2 * math.pi * 3 * v) * (0.5 + v)
    n = (-du, -dv, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(byte(c / length * 0.5 + 0.5) for c in n)


# An sRGB-encoded albedo: a brick-like pattern of mid tones, where decoding sRGB as linear moves values most.
def albedo(x, y):
    row = y // 8
    brick = ((x + (4 if row % 2 else 0)) // 16 + row) % 3
    mortar = y % 8 == 0 or (x + (4 if row % 2 else 0)) % 16 == 0
    base = [(0.72, 0.38, 0.26), (0.62, 0.44, 0.30), (0.55, 0.52, 0.48)][brick]
    shade = 0.85 + 0.15 * math.sin(x * 0.7 + y * 1.3)
    colour = (0.80, 0.78, 0.72) if mortar else tuple(c * shade for c in base)
    return tuple(byte(v) for v in colour)


if __name__ == "__main__":
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    write_png(os.path.join(here, "toon_ramp.png"), 64, 4, ramp)
    write_png(os.path.join(here, "bumps.png"), 64, 64, bumps)
    write_png(os.path.join(here, "albedo_srgb.png"), 64, 64, albedo)
