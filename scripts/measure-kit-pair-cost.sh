#!/usr/bin/env bash
# The cost of one light evaluation per technique on LearnOpenGL's scene (the kit in
# ../shared/peer/learnopengl-8.1, beside the repository, not in it): every technique at two of
# the kit's light counts, where every light reaches every covered pixel, then (frame without the
# geometry pass at B − at A) / (in-range pairs at B − at A) in nanoseconds per (pixel, light)
# pair, on the clock the passes were timed on. The geometry pass and the per-pixel work cancel
# out. With OLD= another build runs interleaved with this one (scripts/lib/bench.py: every round
# runs every case, the order rotated) and both are printed, and then how far apart the two
# builds' images are at the larger count (scripts/compare-pfm.py). Prints the machine and its
# load first and last; read the figures as ratios within one run.
#
#   scripts/measure-kit-pair-cost.sh
#   OLD=/tmp/before/build/manylights TECHNIQUES=deferred,clustered scripts/measure-kit-pair-cost.sh
#
# KIT= the kit's directory; COUNTS= two light counts with a scene in the kit (default 128,512);
# FRAMES= timed frames per run (default 3, after one warm-up frame); ROUNDS= how many times the
# whole set of runs is repeated (default 1). The kit's scenes run as its run-manylights.sh runs
# them: 800x600, Mesa's software rasteriser (LIBGL_ALWAYS_SOFTWARE=1) on LP_NUM_THREADS (2).
set -euo pipefail
cd "$(dirname "$0")/.."
kit=${KIT:-../shared/peer/learnopengl-8.1}
counts=${COUNTS:-128,512}
techniques=${TECHNIQUES:-forward,deferred,volumes,stencil,tiled-quads,tiled,clustered}
if [ ! -f "$kit/manylights-nanosuits-${counts%%,*}.json" ]; then
  echo "measure-kit-pair-cost.sh: no LearnOpenGL kit scenes at '$kit' (set KIT=)" >&2
  exit 1
fi
ML=${ML:-}
if [ -z "$ML" ]; then
  make app >/dev/null
  ML=build/manylights
fi
export ML
software="LIBGL_ALWAYS_SOFTWARE=1 LP_NUM_THREADS=${LP_NUM_THREADS:-2}"
builds=(new)
[ -n "${OLD:-}" ] && builds=(old new)
cases=()
for build in "${builds[@]}"; do
  binary=$ML
  [ "$build" = old ] && binary=$OLD
  for n in ${counts//,/ }; do
    cases+=(--case "$build/$n lights: $software ML=$binary $kit/manylights-nanosuits-$n.json --size 800x600 \
--techniques $techniques --count-work")
  done
done
scripts/lib/bench.py --rounds "${ROUNDS:-1}" --frames "${FRAMES:-3}" --warmup 1 --pairs in_range_pairs \
  --column geometry --per-pair "shading=frame - geometry" "${cases[@]}"
[ -z "${OLD:-}" ] && exit 0
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "old against new image at ${counts#*,} lights (PFM):"
for technique in ${techniques//,/ }; do
  for build in old new; do
    binary=$ML
    [ "$build" = old ] && binary=$OLD
    env LIBGL_ALWAYS_SOFTWARE=1 LP_NUM_THREADS="${LP_NUM_THREADS:-2}" "$binary" render \
      "$kit/manylights-nanosuits-${counts#*,}.json" -o "$out/$build-$technique.pfm" --size 800x600 \
      --technique "$technique" >/dev/null
  done
  scripts/compare-pfm.py "$out/old-$technique.pfm" "$out/new-$technique.pfm" "$technique"
done
