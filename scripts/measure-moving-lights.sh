#!/usr/bin/env bash
# What moving lights cost per frame (render/scene/SceneLights.h: posed on the GPU): tiled and
# clustered on the courtyard with its lights still (bench/courtyard.json) and with every light
# drifting (bench/courtyard-moving.json, `bench --fps 30`: each frame at a new time, its
# posing timed with it), at 16,384 and 1,048,576 lights, 1280x720. With OLD=path/to/manylights
# the other build runs the same cases in each round, interleaved (scripts/lib/bench.py), so that
# both meet the machine's load alike (the build must have `bench --fps`), and the last table is
# old / this. Prints the machine and its load first, then per round, build, scene, technique and
# count the median frame and the median of the `pose lights` pass (- where the build has none).
#
#   scripts/measure-moving-lights.sh
#   OLD=/tmp/old/manylights ROUNDS=3 scripts/measure-moving-lights.sh
set -euo pipefail
cd "$(dirname "$0")/.."
args="--techniques clustered,tiled --lights ${LIGHTS:-16384,1048576} --size ${SIZE:-1280x720} --warmup 1"
builds=(this)
[ -n "${OLD:-}" ] && builds=(old this)
cases=()
for build in "${builds[@]}"; do
  binary=
  [ "$build" = old ] && binary="ML=$OLD"
  cases+=(--case "$build/still: $binary bench/courtyard.json $args")
  cases+=(--case "$build/moving: $binary bench/courtyard-moving.json --fps 30 $args")
done
compare=()
[ -n "${OLD:-}" ] && compare=(--compare)
exec scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "${FRAMES:-3}" --column "pose lights" "${compare[@]}" \
  "${cases[@]}"
