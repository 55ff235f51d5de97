#!/usr/bin/env bash
# What the environment costs (issue 42, docs/performance.md "The environment"): per frame,
# `clustered` at 1280x720 on the courtyard (bench/courtyard.json) at 1,024 lights and on
# scenes/pbr-models.json (whose metallic-roughness materials make the prefiltered lookup), each
# without its `environment` and with builtin:studio (not shown as the background, so that only
# the lighting differs); median frame_ms of FRAMES frames, the cases alternating REPS times. At
# load, environment_ms of a 1024x512 .hdr map (made here: smooth noise and a few bright patches):
# reading, harmonics, upload and prefiltering until the GPU finished. Prints the machine and its
# load first; read the per-frame figures as ratios within one run.
#
#   scripts/measure-environment.sh            FRAMES=5 REPS=3 SIZE=640x360 scripts/measure-environment.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-1280x720}
frames=${FRAMES:-3}
reps=${REPS:-2}
source scripts/measure-common.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - "$out" "$PWD" <<'PY'
import json, math, os, struct, sys
out, root = sys.argv[1], sys.argv[2]
def variants(path, name):
    scene = json.load(open(path))
    # Model paths stay relative to the original scene's folder.
    base = os.path.dirname(os.path.abspath(path))
    for obj in scene.get("objects", []):
        if isinstance(obj.get("mesh"), str):
            obj["mesh"] = os.path.join(base, obj["mesh"])
    scene.pop("environment", None)
    json.dump(scene, open(f"{out}/{name}-without.json", "w"))
    scene["environment"] = {"map": "builtin:studio"}
    json.dump(scene, open(f"{out}/{name}-with.json", "w"))
variants(f"{root}/bench/courtyard.json", "courtyard")
variants(f"{root}/scenes/pbr-models.json", "pbr-models")
# A 1024x512 Radiance file, flat (unencoded) RGBE scanlines.
width, height = 1024, 512
rows = []
for j in range(height):
    theta = math.pi * (j + 0.5) / height
    row = bytearray()
    for i in range(width):
        phi = 2 * math.pi * (i + 0.5) / width
        value = [0.5 + 0.3 * math.cos(theta) + 0.1 * math.sin(5 * phi) * math.sin(3 * theta)] * 3
        if math.cos(theta) > 0.7 and math.sin(3 * phi) > 0.8:
            value = [12.0, 11.0, 9.0]
        v = max(value)
        mantissa, exponent = math.frexp(v)
        scale = mantissa * 256.0 / v
        row += bytes([int(c * scale) for c in value] + [exponent + 128])
    rows.append(bytes(row))
with open(f"{out}/map-1024.hdr", "wb") as f:
    f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
    for row in rows:
        f.write(row)
json.dump({"environment": {"map": "map-1024.hdr"}}, open(f"{out}/map-1024.json", "w"))
PY
frame_ms() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['frame_ms']['median'])" "$1"; }
lighting_ms() {
  python3 -c "import json, sys; print(next(p['wall_ms'] for p in json.load(open(sys.argv[1]))['passes']
if p['name'] == 'lighting'))" "$1"
}
declare -A times passes
cases=(courtyard-without courtyard-with pbr-models-without pbr-models-with)
for ((rep = 0; rep < reps; ++rep)); do
  for name in "${cases[@]}"; do
    lights=()
    [[ $name == courtyard-* ]] && lights=(--lights 1024)
    "$ML" render "$out/$name.json" -o "$out/image.png" --size "$size" --technique clustered "${lights[@]}" \
      --frames "$frames" --stats "$out/stats.json" >/dev/null
    times[$name]+="$(frame_ms "$out/stats.json") "
    passes[$name]+="$(lighting_ms "$out/stats.json") "
  done
done
echo "clustered at $size, $reps runs each of $frames frames: the runs' medians (min-max), and the change of their median"
for scene in courtyard pbr-models; do
  python3 - "$scene" "${times[$scene-without]}" "${times[$scene-with]}" "${passes[$scene-without]}" \
    "${passes[$scene-with]}" <<'PY'
import statistics, sys
name = sys.argv[1]
runs = [list(map(float, arg.split())) for arg in sys.argv[2:]]
def line(what, without, with_):
    a, b = statistics.median(without), statistics.median(with_)
    return (f"{what} without {min(without):.0f}-{max(without):.0f} ms, with builtin:studio "
            f"{min(with_):.0f}-{max(with_):.0f} ms: {b - a:+.1f} ms ({100 * (b - a) / a:+.1f}%)")
print(f"  {name:<11} frame    " + line("", runs[0], runs[1]))
print(f"  {'':<11} lighting " + line("", runs[2], runs[3]))
PY
done
loads=""
for ((rep = 0; rep < reps + 1; ++rep)); do
  "$ML" render "$out/map-1024.json" -o "$out/image.png" --size 64x64 --stats "$out/stats.json" >/dev/null
  loads+="$(python3 -c "import json, sys; print(round(json.load(open(sys.argv[1]))['environment_ms']))" "$out/stats.json") "
done
echo "a 1024x512 .hdr map: environment_ms $loads(read, harmonics, upload, prefiltering until finished)"
