#!/usr/bin/env python3
"""Writes bench/courtyard.json, the benchmark scene of docs/performance.md.

A 60 x 60 m city at night: a 6 x 6 grid of blocks (6 m squares, 4 m streets between them)
split into buildings of varied heights, the middle four blocks replaced by a paved courtyard
with a colonnade, low walls and a fountain. The camera looks down across it at about 55
degrees, so the buildings hide the streets behind them: techniques that cull by depth have
something to cull.

The lights are one point-light set in a thin layer just above the ground (0.1 to 0.4 m), with
`range_reference_count`: `--lights N` scales every range by sqrt(1024 / N), so N times the
area each light covers stays constant and the average number of lights reaching a street
pixel stays about the same from 256 to 65536 lights. The layer is thinner than the smallest
range of the sweep (0.41 m at 65536 lights), so even then most lights reach the ground.

bench/courtyard-moving.json is the same scene with every light drifting (a Lissajous wander of
1 m in x and z, docs/scene-format.md "Animation"): with `bench --fps` it measures what moving
lights cost per frame.

The scenes are files in the repository; this script documents how they were made and remakes them
(deterministically: fixed seed, Python's own Mersenne Twister). Run it from anywhere:
    python3 bench/make-courtyard.py
"""

import json
import os
import random

SEED = 20240611
rng = random.Random(SEED)

BLOCKS = 6  # per axis
BLOCK = 6.0  # block side, m
STREET = 4.0  # street width, m
PITCH = BLOCK + STREET
FLOOR = 60.0


def block_centre(i):
    return (i - (BLOCKS - 1) / 2.0) * PITCH


def rounded(values, digits=2):
    return [round(v, digits) for v in values]


def box(name, material, centre_xz, size, base=0.0):
    """A box standing on the ground (or on `base`)."""
    sx, sy, sz = size
    return {
        "name": name,
        "mesh": {"primitive": "box", "size": rounded([sx, sy, sz])},
        "material": material,
        "transform": {"translate": rounded([centre_xz[0], base + sy / 2.0, centre_xz[1]])},
    }


def cylinder(name, material, centre_xz, radius, height, base=0.0):
    return {
        "name": name,
        "mesh": {"primitive": "cylinder", "radius": radius, "height": height},
        "material": material,
        "transform": {"translate": rounded([centre_xz[0], base + height / 2.0, centre_xz[1]])},
    }


BUILDING_MATERIALS = ["plaster", "brick", "stone", "slate", "sandstone"]


def buildings(bx, bz, objects):
    """Splits one block into 1 to 4 buildings of varied heights."""
    cx, cz = block_centre(bx), block_centre(bz)
    half = BLOCK / 2.0
    layout = rng.choice(["one", "two_x", "two_z", "four", "four"])
    if layout == "one":
        parts = [((cx, cz), (BLOCK, BLOCK))]
    elif layout == "two_x":
        cut = rng.uniform(-1.0, 1.0)
        left = half + cut
        parts = [((cx - half + left / 2.0, cz), (left - 0.5, BLOCK)),
                 ((cx + cut + (half - cut) / 2.0 + 0.25, cz), (half - cut - 0.5, BLOCK))]
    elif layout == "two_z":
        cut = rng.uniform(-1.0, 1.0)
        front = half + cut
        parts = [((cx, cz - half + front / 2.0), (BLOCK, front - 0.5)),
                 ((cx, cz + cut + (half - cut) / 2.0 + 0.25), (BLOCK, half - cut - 0.5))]
    else:
        q = half / 2.0
        parts = [((cx + dx * q, cz + dz * q), (half - 0.4, half - 0.4))
                 for dx in (-1, 1) for dz in (-1, 1)]
    for k, (centre, (sx, sz)) in enumerate(parts):
        # Mostly 3 to 9 m, now and then a tower: a skyline with gaps the camera sees through.
        height = rng.uniform(2.5, 7.0) if rng.random() < 0.85 else rng.uniform(10.0, 14.0)
        objects.append(box(f"building {bx},{bz}.{k}", rng.choice(BUILDING_MATERIALS), centre,
                           (sx, height, sz)))


def courtyard(objects):
    """The middle 2 x 2 blocks and the street between them: a 16 m square plaza."""
    half = BLOCK + STREET / 2.0  # 8 m
    objects.append({
        "name": "plaza paving",
        "mesh": {"primitive": "box", "size": [2.0 * half, 0.1, 2.0 * half]},
        "material": "paving",
        "transform": {"translate": [0, 0.05, 0]},
    })
    # Low walls on each side, with a 4 m gate in the middle of each.
    for side, (nx, nz) in enumerate([(1, 0), (-1, 0), (0, 1), (0, -1)]):
        for end in (-1, 1):
            length = half - 2.0
            along = end * (2.0 + length / 2.0)
            centre = (nx * (half - 0.2) + nz * along, nz * (half - 0.2) + nx * along)
            size = (0.4, 1.2, length) if nx else (length, 1.2, 0.4)
            objects.append(box(f"courtyard wall {side}.{end}", "stone", centre, size))
    # A colonnade 1.5 m inside the walls: columns about 2 m apart, each corner once.
    ring = half - 1.5
    steps = round(2.0 * ring / 2.0)
    spots = []
    for i in range(steps + 1):
        t = round(-ring + i * 2.0 * ring / steps, 3)
        for spot in [(t, -ring), (t, ring), (-ring, t), (ring, t)]:
            if spot not in spots:
                spots.append(spot)
    for (x, z) in spots:
        objects.append(cylinder(f"column {x:+.2f},{z:+.2f}", "marble", (x, z), 0.3, 4.0, base=0.1))
    # The fountain: a basin, a rim and a pillar.
    objects.append(cylinder("fountain basin", "stone", (0.0, 0.0), 2.5, 0.5, base=0.1))
    objects.append({
        "name": "fountain rim",
        "mesh": {"primitive": "torus", "radius": 2.5, "tube": 0.2},
        "material": "marble",
        "transform": {"translate": [0, 0.6, 0]},
    })
    objects.append(cylinder("fountain pillar", "marble", (0.0, 0.0), 0.4, 2.5, base=0.6))
    objects.append({
        "name": "fountain top",
        "mesh": {"primitive": "sphere", "radius": 0.6},
        "material": "marble",
        "transform": {"translate": [0, 3.5, 0]},
    })


def street_furniture(objects):
    """Lamp-post-like columns along the two avenues that cross the city outside the plaza."""
    for i in range(BLOCKS - 1):
        street = block_centre(i) + PITCH / 2.0
        for j in range(BLOCKS):
            along = block_centre(j)
            if abs(along) < 9.0 and abs(street) < 9.0:
                continue  # inside the plaza
            if (i + j) % 2 == 0:
                objects.append(cylinder(f"post x{i}.{j}", "iron", (street, along), 0.15, 3.0))
            else:
                objects.append(cylinder(f"post z{i}.{j}", "iron", (along, street), 0.15, 3.0))


def main():
    objects = [{
        "name": "ground",
        "mesh": {"primitive": "plane", "size": [FLOOR, FLOOR]},
        "material": "asphalt",
    }]
    courtyard_blocks = {(2, 2), (2, 3), (3, 2), (3, 3)}
    for bx in range(BLOCKS):
        for bz in range(BLOCKS):
            if (bx, bz) not in courtyard_blocks:
                buildings(bx, bz, objects)
    courtyard(objects)
    street_furniture(objects)

    scene = {
        "camera": {"eye": [0, 44, 26], "look_at": [0, 0, -4], "up": [0, 1, 0],
                   "fov_y": 50, "near": 0.5, "far": 200},
        "background": [0.02, 0.02, 0.05],
        "ambient": [0.03, 0.03, 0.035],
        "directional": {"direction": [-1, -3, -2], "intensity": [0.12, 0.13, 0.17]},
        "light_sets": [{
            "count": 1024, "seed": 11, "type": "point",
            "min": [-30, 0.1, -30], "max": [30, 0.4, 30],
            "range": [3.25, 6.5], "range_reference_count": 1024,
            "intensity": [0.4, 1.0],
        }],
        "materials": {
            "asphalt": {"diffuse": [0.32, 0.32, 0.34]},
            "paving": {"diffuse": [0.6, 0.56, 0.5], "specular": [0.1, 0.1, 0.1], "shininess": 16},
            "plaster": {"diffuse": [0.75, 0.72, 0.65]},
            "brick": {"diffuse": [0.6, 0.3, 0.22]},
            "stone": {"diffuse": [0.55, 0.55, 0.52]},
            "slate": {"diffuse": [0.35, 0.4, 0.48], "specular": [0.15, 0.15, 0.15], "shininess": 32},
            "sandstone": {"diffuse": [0.78, 0.66, 0.45]},
            "marble": {"diffuse": [0.85, 0.85, 0.82], "specular": [0.4, 0.4, 0.4], "shininess": 64},
            "iron": {"diffuse": [0.15, 0.15, 0.16], "specular": [0.5, 0.5, 0.5], "shininess": 48},
        },
        "objects": objects,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "courtyard.json")
    with open(path, "w") as out:
        out.write(format_scene(scene))
    print(f"wrote {path}: {len(objects)} objects")
    scene["light_sets"][0]["animation"] = {"drift": {"amplitude": [1.0, 0.0, 1.0]}}
    path = os.path.join(here, "courtyard-moving.json")
    with open(path, "w") as out:
        out.write(format_scene(scene))
    print(f"wrote {path}: the same with every light drifting")


def format_scene(scene):
    """JSON with one object per line, so the file diffs and reads well."""
    lines = ["{"]
    keys = list(scene.keys())
    for key in keys:
        value = scene[key]
        last = key == keys[-1]
        if key in ("objects",):
            lines.append(f'  "{key}": [')
            for i, item in enumerate(value):
                comma = "," if i + 1 < len(value) else ""
                lines.append("    " + json.dumps(item) + comma)
            lines.append("  ]" + ("" if last else ","))
        elif key in ("materials",):
            lines.append(f'  "{key}": {{')
            names = list(value.keys())
            for name in names:
                comma = "," if name != names[-1] else ""
                lines.append(f"    {json.dumps(name)}: {json.dumps(value[name])}{comma}")
            lines.append("  }" + ("" if last else ","))
        elif key == "light_sets":
            lines.append(f'  "{key}": [')
            for i, item in enumerate(value):
                comma = "," if i + 1 < len(value) else ""
                lines.append("    " + json.dumps(item) + comma)
            lines.append("  ]" + ("" if last else ","))
        else:
            lines.append(f'  "{key}": {json.dumps(value)}' + ("" if last else ","))
    lines.append("}")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
