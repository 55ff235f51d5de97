#!/usr/bin/env bash
# One build against another on the same machine in one session: every technique's median
# frame on a scene and the median time of one of its passes (PASS, default lighting), the two
# builds interleaved per technique (scripts/lib/bench.py: A B, then B A, ... with REPS=2), and
# the ratios old / new. A change's before and after: OLD is the build of the commit before it.
# For issue 12's courtyard target ("every technique at least 2x faster than the docs' table"):
# build the table's commit elsewhere and pass its binary as OLD.
#
#   OLD=/tmp/table/build/manylights scripts/measure-speedup.sh
#   OLD=... SCENE=default LIGHTS=4096 TECHNIQUES=clustered scripts/measure-speedup.sh   (the built-in scene)
#   OLD=... SCENE=bench/courtyard.json LIGHTS=4096 SIZE=1280x720 TECHNIQUES=clustered,tiled REPS=2 scripts/measure-speedup.sh
#
# Slow techniques (forward, deferred: seconds per frame) get SLOW_FRAMES frames (default 1),
# the others FRAMES (default 3), each after one warm-up frame. Prints the machine and its load
# first and last; read the ratios within one run.
set -euo pipefail
cd "$(dirname "$0")/.."
: "${OLD:?OLD=the manylights binary of the other build}"
scene=${SCENE:-bench/courtyard.json}
[ "$scene" = default ] && scene=
ML=${ML:-}
if [ -z "$ML" ]; then
  make app >/dev/null
  ML=build/manylights
fi
cases=()
for technique in $(echo "${TECHNIQUES:-forward,deferred,volumes,stencil,tiled-quads,tiled,clustered}" | tr , ' '); do
  frames=${FRAMES:-3}
  case $technique in forward | deferred) frames=${SLOW_FRAMES:-1} ;; esac
  args="$scene --techniques $technique --lights ${LIGHTS:-4096} --size ${SIZE:-1280x720} --frames $frames --warmup 1"
  cases+=(--case "old/$technique: ML=$OLD $args" --case "new/$technique: ML=$ML $args")
done
exec scripts/lib/bench.py --rounds "${REPS:-1}" --column "${PASS:-lighting}" --compare "${cases[@]}"
