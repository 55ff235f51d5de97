#!/usr/bin/env bash
# The clustered figures of docs/techniques.md and docs/performance.md: on bench/courtyard.json
# at 1280x720 and 4096 lights, the frame and pass times of clustered and stencil (one bench
# run, so read them as ratios within it), and clustered's light evaluations against the
# pairs in range (--count-work, one untimed frame more). Prints the machine and its load first
# (scripts/lib/bench.py).
#
#   scripts/measure-clustered.sh                 this checkout's build
#   ML=/tmp/before/build/manylights scripts/measure-clustered.sh
#                                                another build, e.g. the list version before
#                                                issue 11: git worktree add /tmp/before 1cda1bf
#                                                && make -C /tmp/before build
set -euo pipefail
cd "$(dirname "$0")/.."
exec scripts/lib/bench.py --frames "${FRAMES:-3}" --warmup 1 --passes \
  --column "evaluations=work.light_evaluations" --column "in range=work.in_range_pairs" \
  --column "evaluations / in range=work.light_evaluations / work.in_range_pairs" \
  --case "courtyard: bench/courtyard.json --techniques clustered,stencil --lights ${LIGHTS:-4096} --size ${SIZE:-1280x720} --count-work"
