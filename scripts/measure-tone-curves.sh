#!/usr/bin/env bash
# Which tone curve shows colours as authored without clipping the many-light hot spots
# (issue 48; docs/display.md, "The default"). For each curve (sRGB-encoded, as the default look
# is) and the classic look:
#   - scenes/studio.json: each coloured sphere's mean displayed colour (its pixels found from
#     the position view: within 0.2% of its radius of its centre, the floor's contact ring left
#     out), its hue and HSV saturation against those of its base colour as authored (the linear
#     base colour, sRGB-encoded): the hue's difference in degrees and the saturation kept in %;
#   - the default scene at 256 lights (the default) and 4096: the share of pixels with a channel
#     at 255 (clipped: the curve's top, where gradations end), and the linear peak (the PFM's
#     largest channel).
# Prints the machine and its load first (scripts/lib/bench.py --machine). Writes its images to
# out/tone-curves/. SIZE=WxH (default 640x360) for every render.
#
#   scripts/measure-tone-curves.sh            CURVES="agx pbr-neutral" scripts/measure-tone-curves.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-640x360}
curves=${CURVES:-agx pbr-neutral aces reinhard}
dir=out/tone-curves
mkdir -p "$dir"
ML=${ML:-$(scripts/lib/bench.py --binary)}
scripts/lib/bench.py --machine

looks=(classic)
for curve in $curves; do looks+=("$curve"); done
display_options() {
  if [ "$1" = classic ]; then echo --classic; else echo "--tonemap $1 --srgb"; fi
}
# ImageMagick (scripts/setup.sh installs it) reads the PNGs to raw 8-bit RGB for Python.
raw() { convert "$1" -depth 8 "rgb:${1%.png}.rgb"; }

"$ML" render scenes/studio.json -o "$dir/studio-position.pfm" --size "$size" --view position >/dev/null
for look in "${looks[@]}"; do
  # shellcheck disable=SC2046  # the options are words
  "$ML" render scenes/studio.json -o "$dir/studio-$look.png" --size "$size" $(display_options "$look") >/dev/null
  raw "$dir/studio-$look.png"
done
for lights in 256 4096; do
  "$ML" render -o "$dir/default-$lights.pfm" --size "$size" --lights "$lights" >/dev/null
  for look in "${looks[@]}"; do
    # shellcheck disable=SC2046
    "$ML" render -o "$dir/default-$lights-$look.png" --size "$size" --lights "$lights" $(display_options "$look") \
      >/dev/null
    raw "$dir/default-$lights-$look.png"
  done
done

python3 - "$dir" "$size" "${looks[@]}" <<'PY'
import array, colorsys, json, math, sys

folder, size, looks = sys.argv[1], sys.argv[2], sys.argv[3:]
width, height = map(int, size.split("x"))


def pfm_rows_top_down(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF", path
        assert tuple(map(int, f.readline().split())) == (width, height), path
        little_endian = float(f.readline()) < 0
        values = array.array("f")
        values.frombytes(f.read())
    if little_endian != (sys.byteorder == "little"):
        values.byteswap()
    # PFM stores rows bottom to top.
    return [values[(height - 1 - y) * width * 3:(height - y) * width * 3] for y in range(height)]


def rgb_bytes(path):
    data = open(path, "rb").read()
    assert len(data) == width * height * 3, path
    return data


def srgb(c):
    c = min(max(c, 0.0), 1.0)
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def hue_saturation(rgb01):
    h, s, _ = colorsys.rgb_to_hsv(*rgb01)
    return 360.0 * h, s


def hue_difference(a, b):
    d = abs(a - b) % 360.0
    return min(d, 360.0 - d)


scene = json.load(open("scenes/studio.json"))
materials = scene["materials"]
spheres = []
for obj in scene["objects"]:
    mesh, material = obj["mesh"], materials.get(obj.get("material"), {})
    if mesh.get("primitive") != "sphere" or "base_color" not in material:
        continue
    authored = [srgb(c) for c in material["base_color"]]
    if hue_saturation(authored)[1] < 0.2:  # greys have no hue to keep
        continue
    centre = obj["transform"]["translate"]
    spheres.append((obj["name"], centre, mesh["radius"], authored))

positions = pfm_rows_top_down(f"{folder}/studio-position.pfm")
masks = {name: [] for name, *_ in spheres}
for y in range(height):
    row = positions[y]
    for x in range(width):
        p = row[x * 3:x * 3 + 3]
        for name, centre, radius, _ in spheres:
            if p[1] > 0.02 and math.dist(p, centre) < radius * 1.002:
                masks[name].append(y * width + x)

print(f"\nscenes/studio.json at {size}: each sphere's mean displayed colour against its base colour")
print(f"  {'look':12s} " + "  ".join(f"{name:>26s}" for name, *_ in spheres))
authored_line = []
for name, _, _, authored in spheres:
    h, s = hue_saturation(authored)
    authored_line.append(f"hue {h:5.1f}, sat {100 * s:5.1f}%".rjust(26))
print(f"  {'authored':12s} " + "  ".join(authored_line))
for look in looks:
    data = rgb_bytes(f"{folder}/studio-{look}.rgb")
    cells = []
    for name, _, _, authored in spheres:
        pixels = masks[name]
        mean = [sum(data[i * 3 + c] for i in pixels) / (255.0 * len(pixels)) for c in range(3)]
        h, s = hue_saturation(mean)
        ah, asat = hue_saturation(authored)
        cells.append(f"hue {hue_difference(h, ah):4.1f} deg off, sat {100 * s / asat:4.0f}%".rjust(26))
    print(f"  {look:12s} " + "  ".join(cells))
print("  (pixels per sphere: " + ", ".join(f"{name} {len(masks[name])}" for name, *_ in spheres) + ")")

for lights in (256, 4096):
    rows = pfm_rows_top_down(f"{folder}/default-{lights}.pfm")
    peak = max(max(r) for r in rows)
    print(f"\nthe default scene, {lights} lights, at {size} (linear peak {peak:.1f}): pixels with a channel at 255")
    for look in looks:
        data = rgb_bytes(f"{folder}/default-{lights}-{look}.rgb")
        clipped = sum(1 for i in range(width * height) if 255 in data[i * 3:i * 3 + 3])
        white = sum(1 for i in range(width * height) if data[i * 3:i * 3 + 3] == b"\xff\xff\xff")
        print(f"  {look:12s} {clipped:7d} ({100 * clipped / (width * height):6.3f} %), all three at 255: {white}")
PY
