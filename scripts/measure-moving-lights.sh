#!/usr/bin/env bash
# What moving lights cost per frame (render/scene/SceneLights.h: posed on the GPU): tiled and
# clustered on the courtyard with its lights still (bench/courtyard.json) and with every light
# drifting (bench/courtyard-moving.json, `bench --fps 30`: each frame at a new time, its
# posing timed with it), at 16,384 and 1,048,576 lights, 1280x720. With OLD=path/to/manylights
# the other build runs the same cases in each round, just before this one, so that both meet
# the machine's load alike (the build must have `bench --fps`). Prints the machine and its load
# first, then per round, build, scene, technique and count the median frame and the median of
# the `pose lights` pass (— where the build has none).
#
#   scripts/measure-moving-lights.sh
#   OLD=/tmp/old/manylights ROUNDS=3 scripts/measure-moving-lights.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
rounds=${ROUNDS:-2}
frames=${FRAMES:-3}
lights=${LIGHTS:-16384,1048576}
size=${SIZE:-1280x720}
builds=("$ML")
[ -n "${OLD:-}" ] && builds=("$OLD" "$ML")
printf '%-5s %-28s %-7s %-10s %8s %9s %8s\n' round build scene technique lights frame_ms pose_ms
for round in $(seq "$rounds"); do
  for build in "${builds[@]}"; do
    for scene in still moving; do
      if [ "$scene" = still ]; then
        args=(bench/courtyard.json)
      else
        args=(bench/courtyard-moving.json --fps 30)
      fi
      "$build" bench "${args[@]}" --techniques clustered,tiled --lights "$lights" --size "$size" \
        --frames "$frames" --warmup 1 2>/dev/null |
        awk -v round="$round" -v build="$build" -v scene="$scene" '
          $1 == "clustered" || $1 == "tiled" {
            pose = "—"
            if (match($0, /pose lights [0-9.]+/)) pose = substr($0, RSTART + 12, RLENGTH - 12)
            printf "%-5s %-28s %-7s %-10s %8s %9s %8s\n", round, build, scene, $1, $2, $4, pose
          }'
    done
  done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
