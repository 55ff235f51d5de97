#!/usr/bin/env bash
# The cost of one light evaluation per technique, measured on the project's own scenes so
# that a regression shows without the LearnOpenGL kit: bench at two light counts with
# --count-work, then (time without the geometry pass at B − at A) / (evaluations at B − at A)
# in nanoseconds of wall time per (pixel, light) pair. The fixed per-frame and per-pixel work
# cancels out; what is left is the light loop's cost per pair, culling included. Prints the
# machine and its load first; read the figures as ratios within one run.
#
#   scripts/measure-pair-cost.sh                         built-in scene, 256 and 1024 lights, 1280x720
#   SCENE=bench/courtyard.json COUNTS=1024,4096 scripts/measure-pair-cost.sh
#   TECHNIQUES=deferred,clustered SIZE=800x600 ML=/tmp/before/build/manylights scripts/measure-pair-cost.sh
set -euo pipefail
cd "$(dirname "$0")/.."
counts=${COUNTS:-256,1024}
size=${SIZE:-1280x720}
techniques=${TECHNIQUES:-deferred,volumes,stencil,tiled-quads,tiled,clustered}
mkdir -p out
csv=out/measure-pair-cost.csv
source scripts/measure-common.sh
"$ML" bench ${SCENE:-} --techniques "$techniques" --lights "$counts" --size "$size" --frames "${FRAMES:-3}" \
  --warmup 1 --count-work --csv "$csv" >/dev/null
python3 - "$csv" <<'PY'
import csv, sys
rows = {}
for row in csv.DictReader(open(sys.argv[1])):
    passes = {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}
    shading_ms = float(row["frame_ms_median"]) - passes.get("geometry", 0.0)
    rows.setdefault(row["technique"], []).append((int(row["lights"]), shading_ms, int(row["light_evaluations"])))
print(f"{'technique':<12} {'lights':>12} {'evaluations':>24} {'ms w/o geometry':>18} {'ns per pair':>12}")
for technique, runs in rows.items():
    (la, ma, ea), (lb, mb, eb) = sorted(runs)[0], sorted(runs)[-1]
    per_pair = (mb - ma) * 1e6 / (eb - ea) if eb != ea else float("nan")
    print(f"{technique:<12} {la:>5} -> {lb:<5} {ea:>11,} -> {eb:<11,} {ma:>8.1f} -> {mb:<8.1f} {per_pair:>12.2f}")
PY
