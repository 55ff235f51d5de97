#!/usr/bin/env bash
# What loading a large environment map costs (issue 48, docs/performance.md "The environment"):
# for each WIDTHS map (a .hdr written here: issue 48's sky of about 1 over a ground of about 0.4,
# and a sun 0.6° across of radiance 20,000, 55° up), `manylights render` of the map alone at
# 64x64, REPS times: environment_ms from --stats (reading, harmonics, the upload of level 0, the
# prefiltering until the GPU finished) and the process's peak resident memory from
# /usr/bin/time -v, beside the size of the map's decoded float pixels (width · height · 3 · 4
# bytes). Prints the machine and its load first.
#
#   scripts/measure-environment-load.sh            WIDTHS="4096 8192" REPS=3 scripts/measure-environment-load.sh
set -euo pipefail
cd "$(dirname "$0")/.."
widths=${WIDTHS:-"1024 4096 8192"}
reps=${REPS:-2}
ML=${ML:-$(scripts/lib/bench.py --binary)}
scripts/lib/bench.py --machine
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for width in $widths; do
  python3 - "$out/map-$width.hdr" "$width" <<'PY'
import math, sys
path, width = sys.argv[1], int(sys.argv[2])
height = width // 2
def rgbe(value):
    v = max(value)
    if v < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(v)
    scale = mantissa * 256.0 / v
    return bytes([min(255, int(c * scale)) for c in value] + [exponent + 128])
def direction(u, v):
    phi, theta = (u - 0.5) * 2 * math.pi, v * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))
def sky(y):
    return [0.45, 0.4, 0.35] if y < 0 else [0.75 + 0.15 * y, 0.85 + 0.2 * y, 1.0 + 0.35 * y]
sun = (0.35, 0.82, 0.45)
norm = math.sqrt(sum(c * c for c in sun))
sun = tuple(c / norm for c in sun)
sun_cos = math.cos(math.radians(0.3))
# The sun's texels: those whose centre lies within 0.3° of it (a flat, unencoded Radiance file;
# the sky depends on the row only, so each row is one texel repeated but near the sun).
theta_sun = math.acos(sun[1])
u_sun = 0.5 + math.atan2(sun[0], -sun[2]) / (2 * math.pi)
with open(path, "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
    for j in range(height):
        v = (j + 0.5) / height
        row = bytearray(rgbe(sky(math.cos(v * math.pi))) * width)
        if abs(v * math.pi - theta_sun) < math.radians(1.0):
            centre = int(u_sun * width)
            reach = int(width / 360 * 2 / max(math.sin(theta_sun), 0.05)) + 2
            for i in range(centre - reach, centre + reach + 1):
                i %= width
                d = direction((i + 0.5) / width, v)
                if sum(a * b for a, b in zip(d, sun)) > sun_cos:
                    row[4 * i:4 * i + 4] = rgbe([20000.0] * 3)
        f.write(bytes(row))
PY
  echo "{\"environment\": {\"map\": \"map-$width.hdr\"}}" >"$out/map-$width.json"
done
echo "map, environment_ms and peak resident memory of $reps runs each, beside the decoded float pixels"
for width in $widths; do
  loads=""
  peaks=""
  for ((rep = 0; rep < reps; ++rep)); do
    /usr/bin/time -v -o "$out/time.txt" "$ML" render "$out/map-$width.json" -o "$out/image.png" --size 64x64 \
      --stats "$out/stats.json" >/dev/null 2>"$out/stderr.txt"
    loads+="$(python3 -c "import json, sys; print(round(json.load(open(sys.argv[1]))['environment_ms']))" \
      "$out/stats.json") "
    peaks+="$(awk '/Maximum resident set size/ {printf "%.0f", $NF / 1024}' "$out/time.txt") "
  done
  decoded=$((width * width / 2 * 12 / 1024 / 1024))
  echo "  ${width}x$((width / 2)): environment_ms ${loads}; peak RSS MiB ${peaks}; decoded pixels $decoded MiB"
  sed 's/^/    stderr: /' "$out/stderr.txt"
done
