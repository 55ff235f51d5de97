#!/usr/bin/env bash
# Frame time of every technique on the animated default scene (the table in docs/viewer.md):
# each technique renders the scene at a mid-animation time (render --time), --frames after one
# warm-up, through scripts/lib/bench.py; every pass with its median on the clock it was timed on.
# Usage: scripts/measure-animated.sh [WxH] [frames] [time]   (ML=, ROUNDS=, BENCH_ARGS= as every
# measure script; docs/performance.md)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1280x720}
frames=${2:-5}
time=${3:-2.5}
cases=()
for technique in forward deferred volumes stencil tiled-quads tiled clustered; do
  cases+=(--case "$technique: render --size $size --technique $technique --time $time")
done
exec scripts/lib/bench.py --frames "$frames" --passes "${cases[@]}"
