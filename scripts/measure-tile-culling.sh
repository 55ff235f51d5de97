#!/usr/bin/env bash
# tiled-quads' CPU culling (render/culling/TileCulling.h) on one thread against every core of
# this machine, in one run (issue 41: at least 1.8x on 2 cores at 262,144 lights).
# MANYLIGHTS_CULLING_THREADS sets the threads; each round runs one thread and `nproc` threads,
# the order swapped every other round. Each line has the `cpu-culling` pass (the culling, the
# quads' bucketing and the upload of the lists: the culling is nearly all of it), median of
# FRAMES after a warm-up, on the courtyard at 1280x720 without the display pass; the last line
# the ratio of the medians over the rounds. Prints the machine and its load first and last.
#
#   scripts/measure-tile-culling.sh
#   LIGHTS=1048576 ROUNDS=2 scripts/measure-tile-culling.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
lights=${LIGHTS:-262144}
rounds=${ROUNDS:-3}
frames=${FRAMES:-9}
size=${SIZE:-1280x720}
cores=$(nproc)
out=out/tile-culling
mkdir -p "$out"
for round in $(seq "$rounds"); do
  order=(1 "$cores")
  [ $((round % 2)) = 0 ] && order=("$cores" 1)
  for threads in "${order[@]}"; do
    MANYLIGHTS_CULLING_THREADS=$threads "$ML" bench bench/courtyard.json --techniques tiled-quads --lights "$lights" \
      --size "$size" --frames "$frames" --warmup 1 --classic --csv "$out/$round-$threads.csv" >"$out/bench.log" 2>&1
    python3 - "$out/$round-$threads.csv" "$round" "$threads" <<'PY'
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
passes = {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}
print(f"round {sys.argv[2]}: {int(row['lights']):,} lights, {sys.argv[3]} culling threads: cpu-culling {passes['cpu-culling']:6.1f} ms")
PY
  done
done
python3 - "$out" "$rounds" "$cores" <<'PY'
import csv, statistics, sys
out, rounds, cores = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def culling(round, threads):
    row = next(csv.DictReader(open(f"{out}/{round}-{threads}.csv")))
    return {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}["cpu-culling"]
serial = statistics.median(culling(r, 1) for r in range(1, rounds + 1))
parallel = statistics.median(culling(r, cores) for r in range(1, rounds + 1))
print(f"median of the rounds: 1 thread {serial:.1f} ms, {cores} threads {parallel:.1f} ms: {serial / parallel:.2f}x")
PY
echo "machine after: load average $(cut -d' ' -f1-3 /proc/loadavg)"
