#!/usr/bin/env bash
# What millions of lights cost before the first frame (docs/performance.md, "Millions of lights:
# start-up and memory"): bench/courtyard.json at each count, clustered at 64x36 (so that the
# frame is small beside the rest), render --stats' lights_ms (generating the light sets),
# renderer_ms (the scene on the GPU: the lights in spatial order, packed and uploaded, the
# technique's programs), their sum, the frame, clustered's gpu_memory_bytes and the process's
# peak resident memory, each also per light. Through scripts/lib/bench.py, which prints the
# machine and its load first and last.
#
#   scripts/measure-startup.sh
#   COUNTS="1048576 16777216" scripts/measure-startup.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cases=()
for n in ${COUNTS:-1048576 4194304 16777216}; do
  cases+=(--case "$n lights: render bench/courtyard.json --lights $n --size 64x36 --technique clustered")
done
exec scripts/lib/bench.py --rounds "${ROUNDS:-1}" \
  --column "lights s=stat.lights_ms / 1000" --column "renderer s=stat.renderer_ms / 1000" \
  --column "together s=stat.lights_ms + stat.renderer_ms / 1000" \
  --column "GPU MiB=counter.gpu_memory_bytes / 1048576" --column "GPU B a light=counter.gpu_memory_bytes / lights" \
  --column "peak resident MiB=peak rss / 1048576" --column "resident B a light=peak rss / lights" "${cases[@]}"
