#!/usr/bin/env bash
# The three ways of timing a frame (docs/performance.md, "Timing on a GPU"): --pass-timing wall
# (a glFinish around every pass, llvmpipe's default), gpu (timer queries, frames issued back to
# back, a GPU's default) and frame (gpu without the per-pass queries), each in turn, the order
# rotated every round (scripts/lib/bench.py). Prints the machine and its load, then per
# technique and timing the median frame time on the CPU clock and between GL_TIMESTAMP queries,
# ms, and the warm-up frames --warmup auto took.
#
#   scripts/measure-pass-timing.sh
#   SCENE=bench/courtyard.json LIGHTS=4096 SIZE=1280x720 ROUNDS=3 scripts/measure-pass-timing.sh
set -euo pipefail
cd "$(dirname "$0")/.."
args="${SCENE:-} --techniques ${TECHNIQUES:-clustered,forward} --size ${SIZE:-320x180}"
[ -n "${LIGHTS:-}" ] && args+=" --lights $LIGHTS"
exec scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "${FRAMES:-5}" --column "gpu frame" \
  --column "warm-up frames=stat.warmup_frames" \
  --case "wall: $args --pass-timing wall" --case "gpu: $args --pass-timing gpu" \
  --case "frame: $args --pass-timing frame"
