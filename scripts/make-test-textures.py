#!/usr/bin/env python3
"""Writes the small textures of the test scenes (tests/scenes/textures/*.png).

Run from the repository root after changing this file; the PNGs are committed so a test run
needs nothing but the build. Pure Python (zlib), so it runs anywhere the build does.

  brick.png        64x64 sRGB colour: red-brown bricks in grey mortar (a diffuse map)
  bumps.png        64x64 tangent-space normal map of a bumpy surface (OpenGL convention, +Y up)
  speckle.png      64x64 specular map: bright bricks, dull mortar
  tilt30.png       4x4 constant normal map: every texel the encoded unit vector tilted 30° from
                   +Z towards the (+X, +Y) diagonal, (sin 30°/√2, sin 30°/√2, cos 30°), for the
                   analytic normal-mapping test (which checks the tangent and the bitangent)
"""
import math
import os
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "scenes", "textures")


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) bytes, y = 0 at the image's top row."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter type: none
        for x in range(width):
            raw.extend(pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) +
                chunk(b"IEND", b""))


def encode_normal(n):
    return tuple(max(0, min(255, round(255 * (0.5 * c + 0.5)))) for c in n)


def is_mortar(x, y):
    # Bricks 16 wide and 8 high, every other row offset by half a brick; 2-texel mortar lines.
    row = y // 8
    shifted = x + (8 if row % 2 else 0)
    return y % 8 < 2 or shifted % 16 < 2


def brick(x, y):
    if is_mortar(x, y):
        return (150, 150, 140)
    shade = 20 * ((x * 7 + y * 13) % 5) // 4  # a little variation from brick to brick
    return (170 + shade, 70 + shade // 2, 50)


def bumps(x, y):
    # Height h = sin(kx)·sin(ky)·0.4/k, so its slopes reach 0.4; n = normalize(−∂h/∂u, −∂h/∂v, 1)
    # with v = −y (image rows run down, the map's +Y is up the image).
    k = 2 * math.pi / 16
    dh_du = 0.4 * math.cos(k * x) * math.sin(k * y)
    dh_dv = -0.4 * math.sin(k * x) * math.cos(k * y)
    n = (-dh_du, -dh_dv, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return encode_normal(tuple(c / length for c in n))


def speckle(x, y):
    return (40, 40, 40) if is_mortar(x, y) else (230, 220, 200)


def tilt30(x, y):
    a = math.radians(30)
    return encode_normal((math.sin(a) / math.sqrt(2), math.sin(a) / math.sqrt(2), math.cos(a)))


def main():
    os.makedirs(OUT, exist_ok=True)
    write_png(os.path.join(OUT, "brick.png"), 64, 64, brick)
    write_png(os.path.join(OUT, "bumps.png"), 64, 64, bumps)
    write_png(os.path.join(OUT, "speckle.png"), 64, 64, speckle)
    write_png(os.path.join(OUT, "tilt30.png"), 4, 4, tilt30)


if __name__ == "__main__":
    main()
