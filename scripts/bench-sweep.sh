#!/usr/bin/env bash
# The sweep of docs/performance.md: every technique the build has, on bench/courtyard.json,
# at 256 to 65536 lights and 1280x720. Writes out/bench.csv, out/bench.txt (the table) and
# docs/images/bench-<size>.svg.
#
# Usage: scripts/bench-sweep.sh
# Settings from the environment, for a quicker look or another machine:
#   LIGHTS=256,1024,4096,16384,65536  SIZE=1280x720  FRAMES=2  WARMUP=1  BUDGET_MS=15000
#   TECHNIQUES=all
#   e.g. LIGHTS=256,1024 SIZE=320x180 FRAMES=1 scripts/bench-sweep.sh
# A technique whose median frame passes BUDGET_MS skips its larger light counts (forward and
# deferred evaluate every light at every pixel: on llvmpipe one of their frames at 65536
# lights takes many minutes). With the budget the sweep takes about 20 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-256,1024,4096,16384,65536}
size=${SIZE:-1280x720}
frames=${FRAMES:-2}
budget=${BUDGET_MS:-15000}
warmup=${WARMUP:-1}
techniques=${TECHNIQUES:-all}

make build >/dev/null
mkdir -p out docs/images
args=(bench bench/courtyard.json --lights "$lights" --size "$size" --frames "$frames" --warmup "$warmup"
      --budget-ms "$budget" --csv out/bench.csv --plot "docs/images/bench-${size//,/_}.svg")
# Work counts are opt-in (COUNT_WORK=1): in_range_pairs is counted by brute force, every
# light at every pixel, which takes minutes per combination at 65536 lights on llvmpipe.
if [ "${COUNT_WORK:-0}" = 1 ]; then
  args+=(--count-work)
fi
if [ "$techniques" != all ]; then
  args+=(--techniques "$techniques")
fi
echo "build/manylights ${args[*]}" >&2
build/manylights "${args[@]}" | tee out/bench.txt
