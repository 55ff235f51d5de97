#!/usr/bin/env python3
"""Compares two PFM images (the renderer's float output) pixel by pixel, in plain Python so that
it runs on a bare GPU server as well as here: prints, for the pixels where either image holds
something, the share of pixels whose largest channel differs by more than 1% of the larger
value (plus 1e-4 for near-black), the largest such relative difference and where, and the mean
absolute difference.

    scripts/compare-pfm.py REFERENCE.pfm OTHER.pfm [LABEL]
"""
import array
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        if kind not in (b"PF", b"Pf"):
            raise SystemExit(f"{path}: not a PFM file")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        values = array.array("f")
        values.frombytes(f.read())
        if (scale < 0) != (sys.byteorder == "little"):
            values.byteswap()
        channels = 3 if kind == b"PF" else 1
        return width, height, channels, values


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    w1, h1, c1, a = read_pfm(sys.argv[1])
    w2, h2, c2, b = read_pfm(sys.argv[2])
    label = sys.argv[3] if len(sys.argv) == 4 else sys.argv[2]
    if (w1, h1, c1) != (w2, h2, c2):
        raise SystemExit(f"{label}: sizes differ ({w1}x{h1}x{c1} against {w2}x{h2}x{c2})")
    pixels = over = 0
    worst = (0.0, 0)
    total = 0.0
    for p in range(w1 * h1):
        x = a[p * c1:(p + 1) * c1]
        y = b[p * c1:(p + 1) * c1]
        if not any(x) and not any(y):
            continue
        pixels += 1
        relative = max(abs(u - v) / (max(abs(u), abs(v)) + 1e-4) for u, v in zip(x, y))
        total += sum(abs(u - v) for u, v in zip(x, y)) / c1
        if relative > 0.01:
            over += 1
        if relative > worst[0]:
            worst = (relative, p)
    if pixels == 0:
        print(f"{label}: both images are black")
        return
    row, column = divmod(worst[1], w1)
    print(f"{label}: {100.0 * over / pixels:.3f}% of {pixels} pixels differ by over 1%; largest "
          f"{100.0 * worst[0]:.2f}% at ({column}, {h1 - 1 - row}); mean |difference| {total / pixels:.2e}")


main()
