#!/usr/bin/env bash
# The stencil technique's GL calls per light and its batches (render/volumes/StencilBatches.h,
# issue 41), with its frame and lighting pass, on the courtyard at 1280x720 at 4,096 and 65,536
# lights (LIGHTS= sets the counts), the median of FRAMES frames. OLD=<binary> runs another build
# as well, interleaved, the order swapped every other round (scripts/lib/bench.py): its
# `gl_calls` are there only if it counts them (gl/CallTally.h) and has bench --json. The calls
# are exact and the same on every run; the times are llvmpipe's on a shared machine. Prints the
# machine and its load first and last.
#
#   scripts/measure-stencil-batches.sh
#   OLD=/tmp/manylights-per-light ROUNDS=2 scripts/measure-stencil-batches.sh
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-4096 65536}
args="bench/courtyard.json --techniques stencil --lights ${lights// /,} --size ${SIZE:-1280x720} --warmup 1 --classic"
cases=(--case "this: $args")
compare=()
if [ -n "${OLD:-}" ]; then
  cases+=(--case "old: ML=$OLD $args")
  compare=(--compare)
fi
exec scripts/lib/bench.py --rounds "${ROUNDS:-1}" --frames "${FRAMES:-3}" --digits 0 "${compare[@]}" \
  --column "gl_calls=counter.gl_calls" --column "per light=counter.gl_calls_per_light" \
  --column "batches=counter.stencil_batches" --column lighting "${cases[@]}"
