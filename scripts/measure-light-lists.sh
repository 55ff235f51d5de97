#!/usr/bin/env bash
# The many-lights figures of docs/performance.md and docs/techniques.md (issue 29): clustered
# and tiled on bench/courtyard.json from 1,024 to 1,048,576 lights at 1280x720, in one bench
# run (read the times as ratios within it), drawn to docs/images/many-lights-1280x720.svg, with
# the GPU memory of each; then the work at 640x360 (--count-work): the pairs in range, the light
# evaluations, the list entries walked, the (cluster, light) pairs, the rebuilds. The frames are
# timed without the display pass (--classic): the techniques' own work. scripts/lib/bench.py
# runs the cases and prints the machine and its load first and last.
#
#   scripts/measure-light-lists.sh
#   OLD=/tmp/before/build/manylights scripts/measure-light-lists.sh
#        also that build's frames at 1,024, 4,096 and 16,384 lights (OLD_LIGHTS), interleaved
#        with this build's (e.g. git worktree add /tmp/before 029410a && make -C /tmp/before build),
#        and both builds' start-up with 1,048,576 lights (a whole render of 64x36)
#   OLD=... OLD_ONLY=1 OLD_LIGHTS=1024,16384,1048576 scripts/measure-light-lists.sh
#        that comparison alone (ROUNDS= rounds, default 2, the builds' order swapped every other
#        round; each line the frame and its clusters, pairs, sort or mask lists and lighting
#        passes, ms)
#   LIGHTS=1024,16384 SIZE=640x360 FRAMES=1 scripts/measure-light-lists.sh   a quicker look
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-1024,4096,16384,65536,262144,1048576}
size=${SIZE:-1280x720}
frames=${FRAMES:-2}
mkdir -p docs/images
if [ -n "${OLD:-}" ]; then
  ML=${ML:-}
  if [ -z "$ML" ]; then
    make app >/dev/null
    ML=build/manylights
  fi
  # A build from before the display pass (029410a) has no --classic and no display pass to leave out.
  classic() { "$1" bench --help | grep -q -- --classic && echo --classic || true; }
  args="bench/courtyard.json --techniques clustered,tiled --lights ${OLD_LIGHTS:-1024,4096,16384} --size $size --warmup 1"
  echo "== the build before against this one, interleaved (frame ms, median of $frames)"
  scripts/lib/bench.py --rounds "${ROUNDS:-2}" --frames "$frames" --compare \
    --column clusters --column "cluster pairs" --column "pair sort" --column "mask lists" --column lighting \
    --case "before: ML=$OLD $args $(classic "$OLD")" --case "this: ML=$ML $args $(classic "$ML")"
  # Start-up with a million lights: a whole render of a tiny image (the lights' sort and upload,
  # render/scene/SceneLights.h, dominate it), the two builds interleaved.
  echo "== start-up: a render of 1,048,576 lights at 64x36"
  startup="render bench/courtyard.json --lights 1048576 --size 64x36"
  scripts/lib/bench.py --rounds 2 --column "process s" --column "renderer_ms=stat.renderer_ms" --compare \
    --case "before: ML=$OLD $startup" --case "this: ML=$ML $startup"
  [ -n "${OLD_ONLY:-}" ] && exit 0
fi
echo "== bench bench/courtyard.json --techniques clustered,tiled --lights $lights --size $size --classic; the work at 640x360"
args="bench/courtyard.json --techniques clustered,tiled --lights $lights --classic"
exec scripts/lib/bench.py --frames "$frames" --warmup 1 --passes \
  --column "GPU MiB=counter.gpu_memory_bytes / 1048576" \
  --column "in range=work.in_range_pairs" --column "evaluations=work.light_evaluations" \
  --column "/ in range=work.light_evaluations / work.in_range_pairs" \
  --column "entries walked=counter.cluster_list_visits" \
  --column "walked / in range=counter.cluster_list_visits / work.in_range_pairs" \
  --column "cluster pairs=counter.cluster_pairs" --column "rebuilds=counter.cluster_rebuilds" \
  --case "timed: $args --size $size --plot docs/images/many-lights-${size}.svg" \
  --case "work: $args --size 640x360 --count-work --frames 1"
