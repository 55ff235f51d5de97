#!/usr/bin/env python3
"""Writes an OBJ holding N shifted copies of a positions-and-faces OBJ, for measuring how
loading time grows with the file's size (docs/performance.md, "Loading model files").

    scripts/repeat-obj.py 4 assets/models/stanford-bunny.obj /tmp/bunny4.obj
"""
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    copies, source, target = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    lines = open(source).read().splitlines()
    positions = [line.split()[1:4] for line in lines if line.startswith("v ")]
    faces = [[int(corner.split("/")[0]) for corner in line.split()[1:]] for line in lines if line.startswith("f ")]
    # Shifted along x by a little more than the model's width, so the copies do not overlap.
    xs = [float(p[0]) for p in positions]
    shift = 1.1 * (max(xs) - min(xs))
    with open(target, "w") as out:
        for k in range(copies):
            for x, y, z in positions:
                out.write(f"v {float(x) + k * shift:.6g} {y} {z}\n")
        for k in range(copies):
            for face in faces:
                out.write("f " + " ".join(str(i + k * len(positions)) for i in face) + "\n")


if __name__ == "__main__":
    main()
