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
# FRAMES= timed frames per run (default 3, after one warm-up frame); ROUNDS= how many times the
# whole set of runs is repeated (default 1). Within a round every technique and build runs at
# one count before the next count, so that a machine whose load changes meets them alike; with
# more than one round each round's figure is printed, then the range.
set -euo pipefail
cd "$(dirname "$0")/.."
kit=${KIT:-../shared/peer/learnopengl-8.1}
counts=${COUNTS:-128,512}
techniques=${TECHNIQUES:-forward,deferred,volumes,stencil,tiled-quads,tiled,clustered}
frames=${FRAMES:-3}
rounds=${ROUNDS:-1}
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
for round in $(seq "$rounds"); do
  for n in ${counts//,/ }; do
    for technique in ${techniques//,/ }; do
      for build in "${builds[@]}"; do
        OUT_DIR=$out/$round/$build ML=$(binary_of "$build") "$kit/run-manylights.sh" "$n" "$frames" "$technique" \
          >/dev/null
        echo "[$build] round $round: $technique $n lights done"
      done
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$out" "$counts" "$techniques" "$rounds" "${builds[@]}" <<'PY'
import json, sys
out, counts, techniques, rounds, builds = sys.argv[1], sys.argv[2].split(","), sys.argv[3].split(","), int(sys.argv[4]), sys.argv[5:]
pairs = {n: json.load(open(f"{out}/pairs/ml-{n}-deferred.json"))["in_range_pairs"] for n in counts}
def shading(round, build, n, technique):
    stats = json.load(open(f"{out}/{round}/{build}/ml-{n}-{technique}.json"))
    geometry = sum(p["wall_ms"] for p in stats["passes"] if p["name"] == "geometry")
    return stats["frame_ms"]["median"], stats["frame_ms"]["median"] - geometry
a, b = counts
print(f"in-range pairs: {pairs[a]:,} at {a} lights, {pairs[b]:,} at {b}")
print(f"{'round':<5} {'technique':<12} {'build':<5} {'frame ms ' + a + ' -> ' + b:>24} {'w/o geometry':>22} {'ns per pair':>12}")
ns = {}
for round in range(1, rounds + 1):
    for technique in techniques:
        for build in builds:
            (frame_a, shade_a), (frame_b, shade_b) = shading(round, build, a, technique), shading(round, build, b, technique)
            ns.setdefault((technique, build), []).append((shade_b - shade_a) * 1e6 / (pairs[b] - pairs[a]))
            print(f"{round:<5} {technique:<12} {build:<5} {frame_a:11.1f} -> {frame_b:9.1f} {shade_a:9.1f} -> {shade_b:9.1f} "
                  f"{ns[technique, build][-1]:12.2f}")
if rounds > 1:
    print("ns per pair over the rounds, and against deferred's of the same round and build:")
    for technique in techniques:
        for build in builds:
            values = ns[technique, build]
            line = f"{technique:<12} {build:<5} {min(values):6.2f} - {max(values):5.2f}"
            if ("deferred", build) in ns and technique != "deferred":
                ratios = [v / d for v, d in zip(values, ns["deferred", build])]
                line += f"   x deferred {min(ratios):5.2f} - {max(ratios):4.2f}"
            print(line)
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
