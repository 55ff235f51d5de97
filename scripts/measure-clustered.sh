#!/usr/bin/env bash
# The clustered figures of docs/techniques.md and docs/performance.md: on bench/courtyard.json
# at 1280x720 and 4096 lights, the frame and pass times of clustered and stencil (one bench
# run, so read them as ratios within it), and clustered's light evaluations against the
# pairs in range. Prints the machine and its load first.
#
#   scripts/measure-clustered.sh                 this checkout's build
#   ML=/tmp/before/build/manylights scripts/measure-clustered.sh
#                                                another build, e.g. the list version before
#                                                issue 11: git worktree add /tmp/before 1cda1bf
#                                                && make -C /tmp/before build
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-4096}
size=${SIZE:-1280x720}
frames=${FRAMES:-3}
mkdir -p out
source scripts/measure-common.sh
"$ML" bench bench/courtyard.json --techniques clustered,stencil --lights "$lights" --size "$size" \
  --frames "$frames" --warmup 1 | tail -n 3
"$ML" render bench/courtyard.json -o out/measure-clustered.png --lights "$lights" --size "$size" \
  --technique clustered --count-work --stats out/measure-clustered.json
python3 - out/measure-clustered.json <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
evaluations, in_range = stats["light_evaluations"], stats["in_range_pairs"]
print(f"clustered light evaluations {evaluations:,}, in range {in_range:,}: {evaluations / in_range:.2f} x")
PY
