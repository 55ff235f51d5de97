#!/usr/bin/env bash
# The cost of one light evaluation per technique on LearnOpenGL's scene (the kit in
# ../shared/peer/learnopengl-8.1, beside the repository, not in it): every technique at two of
# the kit's light counts, where every light reaches every covered pixel, then (frame without the
# geometry pass at B − at A) / (in-range pairs at B − at A) in nanoseconds of wall time per
# (pixel, light) pair. The geometry pass and the per-pixel work cancel out. With OLD= another
# build runs interleaved with this one (old, new per technique and count) and both are printed,
# and then how far apart the two builds' images are at the larger count (PFM, in 1/255 steps).
# Prints the machine and its load first; read the figures as ratios within one run.
#
#   scripts/measure-kit-pair-cost.sh
#   OLD=/tmp/before/build/manylights TECHNIQUES=deferred,clustered scripts/measure-kit-pair-cost.sh
#
# KIT= the kit's directory; COUNTS= two light counts with a scene in the kit (default 128,512);
# FRAMES= timed frames per run (default 3, after one warm-up frame).
set -euo pipefail
cd "$(dirname "$0")/.."
kit=${KIT:-../shared/peer/learnopengl-8.1}
counts=${COUNTS:-128,512}
techniques=${TECHNIQUES:-forward,deferred,volumes,stencil,tiled-quads,tiled,clustered}
frames=${FRAMES:-3}
if [ ! -x "$kit/run-manylights.sh" ]; then
  echo "measure-kit-pair-cost.sh: no LearnOpenGL kit at '$kit' (set KIT=)" >&2
  exit 1
fi
source scripts/measure-common.sh
builds=(new)
[ -n "${OLD:-}" ] && builds=(old new)
echo "kit: $kit; counts $counts; old: ${OLD:-none}; new: $ML"
out=out/kit-pair-cost
rm -rf "$out"
binary_of() { if [ "$1" = old ]; then echo "$OLD"; else echo "$ML"; fi; }
# The pairs depend on the scene alone: counted once per light count.
for n in ${counts//,/ }; do
  OUT_DIR=$out/pairs ML=$ML "$kit/run-manylights.sh" "$n" 1 deferred --count-work >/dev/null
done
for technique in ${techniques//,/ }; do
  for n in ${counts//,/ }; do
    for build in "${builds[@]}"; do
      OUT_DIR=$out/$build ML=$(binary_of "$build") "$kit/run-manylights.sh" "$n" "$frames" "$technique" >/dev/null
      echo "[$build] $technique $n lights done"
    done
  done
done
python3 - "$out" "$counts" "$techniques" "${builds[@]}" <<'PY'
import json, sys
out, counts, techniques, builds = sys.argv[1], sys.argv[2].split(","), sys.argv[3].split(","), sys.argv[4:]
pairs = {n: json.load(open(f"{out}/pairs/ml-{n}-deferred.json"))["in_range_pairs"] for n in counts}
def shading(build, n, technique):
    stats = json.load(open(f"{out}/{build}/ml-{n}-{technique}.json"))
    geometry = sum(p["wall_ms"] for p in stats["passes"] if p["name"] == "geometry")
    return stats["frame_ms"]["median"], stats["frame_ms"]["median"] - geometry
a, b = counts
print(f"in-range pairs: {pairs[a]:,} at {a} lights, {pairs[b]:,} at {b}")
print(f"{'technique':<12} {'build':<5} {'frame ms ' + a + ' -> ' + b:>24} {'w/o geometry':>22} {'ns per pair':>12}")
for technique in techniques:
    for build in builds:
        (frame_a, shade_a), (frame_b, shade_b) = shading(build, a, technique), shading(build, b, technique)
        ns = (shade_b - shade_a) * 1e6 / (pairs[b] - pairs[a])
        print(f"{technique:<12} {build:<5} {frame_a:11.1f} -> {frame_b:9.1f} {shade_a:9.1f} -> {shade_b:9.1f} {ns:12.2f}")
PY
[ -z "${OLD:-}" ] && exit 0
for technique in ${techniques//,/ }; do
  for build in old new; do
    LIBGL_ALWAYS_SOFTWARE=1 LP_NUM_THREADS=${LP_NUM_THREADS:-2} "$(binary_of "$build")" render \
      "$kit/manylights-nanosuits-${counts#*,}.json" -o "$out/$build-$technique.pfm" --size 800x600 \
      --technique "$technique" >/dev/null
  done
done
python3 - "$out" "$techniques" "${counts#*,}" <<'PY'
import struct, sys
out, techniques, lights = sys.argv[1], sys.argv[2].split(","), sys.argv[3]
def floats(path):
    data = open(path, "rb").read()
    header = data.split(b"\n", 3)
    width, height = map(int, header[1].split())
    return struct.unpack(f"<{3 * width * height}f", header[3][: 12 * width * height])
print(f"old against new image at {lights} lights (PFM): largest difference in 1/255 steps, channels that differ")
for technique in techniques:
    old, new = floats(f"{out}/old-{technique}.pfm"), floats(f"{out}/new-{technique}.pfm")
    differences = [abs(a - b) for a, b in zip(old, new)]
    print(f"{technique:<12} {255 * max(differences):10.4f} {sum(d > 0 for d in differences):>10,} of {len(differences):,}")
PY
