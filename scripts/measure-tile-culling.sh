#!/usr/bin/env bash
# tiled-quads' CPU culling (render/culling/TileCulling.h) on one thread against every core of
# this machine, in one run (issue 41: at least 1.8x on 2 cores at 262,144 lights).
# MANYLIGHTS_CULLING_THREADS sets the threads; each round runs one thread and `nproc` threads,
# the order swapped every other round (scripts/lib/bench.py). Each line has the `cpu-culling`
# pass (the culling, the quads' bucketing and the upload of the lists: the culling is nearly
# all of it), median of FRAMES after a warm-up, on the courtyard at 1280x720 without the display
# pass; the last table the ratio of the medians over the rounds. The culling runs on the CPU, so
# its pass is timed on the CPU clock (--pass-timing wall) under either driver profile
# (BENCH_ARGS='--driver-profile gpu'). Prints the machine and its load first and last.
#
#   scripts/measure-tile-culling.sh
#   LIGHTS=1048576 ROUNDS=2 scripts/measure-tile-culling.sh
#   ML=/tmp/other/manylights BENCH_ARGS='--driver-profile gpu' scripts/measure-tile-culling.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cores=$(nproc)
args="bench/courtyard.json --techniques tiled-quads --lights ${LIGHTS:-262144} --size ${SIZE:-1280x720} --warmup 1"
args+=" --classic --pass-timing wall"
exec scripts/lib/bench.py --rounds "${ROUNDS:-3}" --frames "${FRAMES:-9}" --column cpu-culling --compare \
  --case "1 thread: MANYLIGHTS_CULLING_THREADS=1 $args" \
  --case "$cores threads: MANYLIGHTS_CULLING_THREADS=$cores $args"
