#!/usr/bin/env bash
# The share of the grid a light must cover to go to the global list of tiled and clustered
# (render/culling/ClusterLists.h, kGlobalLightGridFraction): frames at several shares, set through
# MANYLIGHTS_GLOBAL_LIGHT_FRACTION (above 1: no global list but for unbounded lights), on scenes
# whose lights cover from a few tiles to all of the view: the courtyard at 64 and 256 lights
# (its ranges grow as the count falls) and the default scene, at 1280x720 without the display
# pass. Each round runs every share once per scene before the next round, the order rotated
# (scripts/lib/bench.py), so that a machine whose load changes meets them alike; the table has
# the global lights, the pairs and the frame (median of FRAMES after a warm-up) over the rounds.
# Prints the machine and its load first and last.
#
#   scripts/measure-global-fraction.sh
#   FRACTIONS=0.25,0.5 ROUNDS=3 scripts/measure-global-fraction.sh
set -euo pipefail
cd "$(dirname "$0")/.."
fractions=${FRACTIONS:-0.125,0.25,0.5,0.75,2}
args="--techniques clustered,tiled --size ${SIZE:-1280x720} --classic --warmup 1"
cases=()
for fraction in ${fractions//,/ }; do
  environment="MANYLIGHTS_GLOBAL_LIGHT_FRACTION=$fraction LP_NUM_THREADS=${LP_NUM_THREADS:-2}"
  cases+=(--case "share $fraction/courtyard: $environment bench/courtyard.json --lights 64,256 $args")
  cases+=(--case "share $fraction/default: $environment --lights 256 $args")
done
exec scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "${FRAMES:-3}" --digits 0 \
  --column "global=counter.global_lights" --column "pairs=counter.cluster_pairs" "${cases[@]}"
