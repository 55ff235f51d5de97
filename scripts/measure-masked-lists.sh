#!/usr/bin/env bash
# The light lists of tiled and clustered built from bit masks against the same lists built by
# the pair sort (render/culling/ClusterLists.h, kMaskedListLights; MANYLIGHTS_MASKED_LIST_LIGHTS
# sets the limit: 0 sorts every frame, 16384 masks frames of up to 16,384 lights). For each
# light count of the courtyard at 1280x720 without the display pass, both builders of lists
# in turn, the order swapped every other round; each line has the frame (median of FRAMES
# after a warm-up), the list passes together (`cluster pairs`, `cluster lists` and `pair sort`
# or `mask lists`) and the lighting, ms. Prints the machine and its load first.
#
#   scripts/measure-masked-lists.sh
#   LIGHTS=1024 TECHNIQUES=clustered ROUNDS=4 scripts/measure-masked-lists.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
lights=${LIGHTS:-1024,2048,4096,8192,16384}
techniques=${TECHNIQUES:-clustered,tiled}
rounds=${ROUNDS:-2}
frames=${FRAMES:-5}
size=${SIZE:-1280x720}
masked_limit=${MASKED_LIMIT:-16384}
out=out/masked-lists
mkdir -p "$out"
for round in $(seq "$rounds"); do
  limits=("$masked_limit" 0)
  [ $((round % 2)) = 0 ] && limits=(0 "$masked_limit")
  for limit in "${limits[@]}"; do
    MANYLIGHTS_MASKED_LIST_LIGHTS=$limit "$ML" bench bench/courtyard.json --techniques "$techniques" \
      --lights "$lights" --size "$size" --frames "$frames" --warmup 1 --classic --csv "$out/$limit.csv" >/dev/null
    python3 - "$out/$limit.csv" "round $round $([ "$limit" = 0 ] && echo sorted || echo masked)" <<'PY'
import csv, sys
lists = ("cluster pairs", "cluster lists", "pair sort", "mask lists")
for row in csv.DictReader(open(sys.argv[1])):
    passes = {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}
    print(f"{sys.argv[2]}: {row['technique']:<9} {int(row['lights']):>6,} lights: frame {float(row['frame_ms_median']):6.1f}"
          f"  lists {sum(passes.get(name, 0.0) for name in lists):5.1f}  lighting {passes['lighting']:5.1f} ms")
PY
  done
done
echo "machine after: load average $(cut -d' ' -f1-3 /proc/loadavg)"
