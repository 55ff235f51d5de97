#!/usr/bin/env bash
# The light lists of tiled and clustered built from bit masks against the same lists built by
# the pair sort (render/culling/ClusterLists.h, kMaskedListLights; MANYLIGHTS_MASKED_LIST_LIGHTS
# sets the limit: 0 sorts every frame, 16384 masks frames of up to 16,384 lights). For each
# light count of the courtyard at 1280x720 without the display pass, both builders of lists
# in turn, the order swapped every other round (scripts/lib/bench.py); each line has the frame
# (median of FRAMES after a warm-up), the list passes together (`cluster pairs`, `cluster
# lists` and `pair sort` or `mask lists`) and the lighting, ms, and the last table masked /
# sorted. Prints the machine and its load first and last.
#
#   scripts/measure-masked-lists.sh
#   LIGHTS=1024 TECHNIQUES=clustered ROUNDS=4 scripts/measure-masked-lists.sh
set -euo pipefail
cd "$(dirname "$0")/.."
args="bench/courtyard.json --techniques ${TECHNIQUES:-clustered,tiled} --lights ${LIGHTS:-1024,2048,4096,8192,16384}"
args+=" --size ${SIZE:-1280x720} --warmup 1 --classic"
exec scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "${FRAMES:-5}" --compare \
  --column "lists=cluster pairs + cluster lists + pair sort + mask lists" --column lighting \
  --case "masked: MANYLIGHTS_MASKED_LIST_LIGHTS=${MASKED_LIMIT:-16384} $args" \
  --case "sorted: MANYLIGHTS_MASKED_LIST_LIGHTS=0 $args"
