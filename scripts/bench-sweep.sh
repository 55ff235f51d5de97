#!/usr/bin/env bash
# The sweep of docs/performance.md: every technique the build has, on bench/courtyard.json,
# at 256 to 65536 lights and 1280x720. Writes out/bench.csv, out/bench.txt (the table) and
# docs/images/bench-<size>.svg.
#
# Usage: scripts/bench-sweep.sh
# Settings from the environment, for a quicker look or another machine:
#   LIGHTS=256,1024,4096,16384,65536  SIZE=1280x720  FRAMES=3  WARMUP=1  TECHNIQUES=all
#   e.g. LIGHTS=256,1024 SIZE=320x180 FRAMES=1 scripts/bench-sweep.sh
# On llvmpipe the full sweep takes hours: forward and deferred evaluate every light at every
# pixel, so at 65536 lights one of their frames takes many minutes. On a GPU it takes minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-256,1024,4096,16384,65536}
size=${SIZE:-1280x720}
frames=${FRAMES:-3}
warmup=${WARMUP:-1}
techniques=${TECHNIQUES:-all}

make build >/dev/null
mkdir -p out docs/images
args=(bench bench/courtyard.json --lights "$lights" --size "$size" --frames "$frames" --warmup "$warmup"
      --count-work --csv out/bench.csv --plot "docs/images/bench-${size//,/_}.svg")
if [ "$techniques" != all ]; then
  args+=(--techniques "$techniques")
fi
echo "build/manylights ${args[*]}" >&2
build/manylights "${args[@]}" | tee out/bench.txt
