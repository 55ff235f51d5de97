#!/usr/bin/env bash
# deferred's and clustered's lighting as a full-screen fragment pass against a compute pass
# (--lighting-stage; docs/techniques.md, "The lighting stage"). For each scene and technique
# both stages in turn, the order swapped every other round; each line has the frame and the
# lighting passes together (median of FRAMES after a warm-up, ms). Prints the machine and its
# load first.
#
#   scripts/measure-lighting-stage.sh
#   LIGHTS=1024 SIZE=1920x1080 ROUNDS=3 scripts/measure-lighting-stage.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
lights=${LIGHTS:-1024}
size=${SIZE:-1280x720}
rounds=${ROUNDS:-2}
frames=${FRAMES:-5}
out=out/lighting-stage
mkdir -p "$out"
for round in $(seq "$rounds"); do
  stages=(fragment compute)
  [ $((round % 2)) = 0 ] && stages=(compute fragment)
  for scene in default courtyard; do
    for stage in "${stages[@]}"; do
      args=()
      [ "$scene" = courtyard ] && args=(bench/courtyard.json --lights "$lights")
      "$ML" bench "${args[@]}" --techniques deferred,clustered --size "$size" --frames "$frames" --warmup 1 \
        --classic --pass-timing wall --lighting-stage "$stage" --csv "$out/$scene-$stage.csv" >/dev/null 2>&1
      python3 - "$out/$scene-$stage.csv" "round $round $scene $stage" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    passes = [p.split(":") for p in row["passes"].split(";")]
    lighting = sum(float(p[1]) for p in passes if p[0] == "lighting")
    print(f"{sys.argv[2]:<28} {row['technique']:<10} {row['lights']:>6} lights  frame {float(row['frame_ms_median']):7.1f} ms"
          f"  lighting {lighting:7.1f} ms")
PY
    done
  done
done
