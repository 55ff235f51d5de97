#!/usr/bin/env bash
# deferred's and clustered's lighting as a full-screen fragment pass against a compute pass
# (--lighting-stage; docs/techniques.md, "The lighting stage"). For each scene both stages in
# turn, the order rotated every round (scripts/lib/bench.py); each line has the frame and the
# lighting pass (median of FRAMES after a warm-up, ms, timed on the wall clock: --pass-timing
# wall), and the last table fragment / compute. Prints the machine and its load first and last.
#
#   scripts/measure-lighting-stage.sh
#   LIGHTS=1024 SIZE=1920x1080 ROUNDS=3 scripts/measure-lighting-stage.sh
set -euo pipefail
cd "$(dirname "$0")/.."
args="--techniques deferred,clustered --size ${SIZE:-1280x720} --warmup 1 --classic --pass-timing wall"
cases=()
for scene in default courtyard; do
  scene_args=
  [ "$scene" = courtyard ] && scene_args="bench/courtyard.json --lights ${LIGHTS:-1024}"
  for stage in fragment compute; do
    cases+=(--case "$stage/$scene: $scene_args $args --lighting-stage $stage")
  done
done
exec scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "${FRAMES:-5}" --column lighting --compare "${cases[@]}"
