#!/usr/bin/env bash
# The three ways of timing a frame (docs/performance.md, "Timing on a GPU"): --pass-timing wall
# (a glFinish around every pass, llvmpipe's default), gpu (timer queries, frames issued back to
# back, a GPU's default) and frame (gpu without the per-pass queries), each in turn, the order
# rotated every round. Prints the machine and its load, then per technique and timing the
# median frame time on the CPU clock and between GL_TIMESTAMP queries, ms.
#
#   scripts/measure-pass-timing.sh
#   SCENE=bench/courtyard.json LIGHTS=4096 SIZE=1280x720 ROUNDS=3 scripts/measure-pass-timing.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
scene=${SCENE:-}
lights=${LIGHTS:-}
size=${SIZE:-320x180}
techniques=${TECHNIQUES:-clustered,forward}
frames=${FRAMES:-5}
rounds=${ROUNDS:-2}
out=out/pass-timing
mkdir -p "$out"
timings=(wall gpu frame)
for round in $(seq "$rounds"); do
  for i in 0 1 2; do
    timing=${timings[$(((i + round - 1) % 3))]}
    args=(bench)
    [ -n "$scene" ] && args+=("$scene")
    [ -n "$lights" ] && args+=(--lights "$lights")
    "$ML" "${args[@]}" --techniques "$techniques" --size "$size" --frames "$frames" \
      --pass-timing "$timing" --csv "$out/$timing.csv" >/dev/null 2>&1
    python3 - "$out/$timing.csv" "round $round" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print(f"{sys.argv[2]}  {row['technique']:<12} {row['pass_timing']:<6} frame {float(row['frame_ms_median']):8.1f} ms"
          f"  gpu {float(row['frame_gpu_ms_median']):8.1f} ms  (warm-up {row['warmup_frames']} frames)")
PY
  done
done
