#!/usr/bin/env bash
# The cost of one light evaluation per technique, measured on the project's own scenes so
# that a regression shows without the LearnOpenGL kit: bench at two light counts with
# --count-work, then (frame without the geometry pass at B − at A) / (evaluations at B − at A)
# in nanoseconds per (pixel, light) pair, on the clock the passes were timed on
# (scripts/lib/bench.py). The fixed per-frame and per-pixel work cancels out; what is left is
# the light loop's cost per pair, culling included. Prints the machine and its load first; read
# the figures as ratios within one run.
#
#   scripts/measure-pair-cost.sh                         built-in scene, 256 and 1024 lights, 1280x720
#   SCENE=bench/courtyard.json COUNTS=1024,4096 scripts/measure-pair-cost.sh
#   TECHNIQUES=deferred,clustered SIZE=800x600 ML=/tmp/before/build/manylights scripts/measure-pair-cost.sh
set -euo pipefail
cd "$(dirname "$0")/.."
techniques=${TECHNIQUES:-deferred,volumes,stencil,tiled-quads,tiled,clustered}
exec scripts/lib/bench.py --rounds "${ROUNDS:-1}" --frames "${FRAMES:-3}" --warmup 1 --column geometry \
  --per-pair "shading=frame - geometry" \
  --case "${SCENE:-default}: ${SCENE:-} --techniques $techniques --lights ${COUNTS:-256,1024} --size ${SIZE:-1280x720} --count-work"
