#!/usr/bin/env bash
# One build against another on the same machine in one session: every technique's median
# frame on a scene, the two builds interleaved per technique (A B A B with REPS=2), and the
# ratio old / new. For issue 12's courtyard target ("every technique at least 2x faster than
# the docs' table"): build the table's commit elsewhere and pass its binary as OLD.
#
#   OLD=/tmp/table/build/manylights scripts/measure-speedup.sh
#   OLD=... SCENE=bench/courtyard.json LIGHTS=4096 SIZE=1280x720 TECHNIQUES=clustered,tiled REPS=2 scripts/measure-speedup.sh
#
# Slow techniques (forward, deferred: seconds per frame) get SLOW_FRAMES frames (default 1),
# the others FRAMES (default 3), each after one warm-up frame. Prints the machine and its load
# first; read the ratios within one run.
set -euo pipefail
cd "$(dirname "$0")/.."
: "${OLD:?OLD=the manylights binary of the other build}"
scene=${SCENE:-bench/courtyard.json}
lights=${LIGHTS:-4096}
size=${SIZE:-1280x720}
techniques=${TECHNIQUES:-forward,deferred,volumes,stencil,tiled-quads,tiled,clustered}
reps=${REPS:-1}
source scripts/measure-common.sh
echo "old: $OLD; new: $ML; $scene, $lights lights, $size, $reps run(s) of each build per technique"
mkdir -p out
results=out/measure-speedup.txt
: > "$results"
for technique in ${techniques//,/ }; do
  frames=${FRAMES:-3}
  case $technique in forward | deferred) frames=${SLOW_FRAMES:-1} ;; esac
  for ((rep = 0; rep < reps; ++rep)); do
    for side in old new; do
      binary=$ML
      [ "$side" = old ] && binary=$OLD
      csv=out/measure-speedup.csv
      "$binary" bench "$scene" --techniques "$technique" --lights "$lights" --size "$size" --frames "$frames" \
        --warmup 1 --csv "$csv" >/dev/null
      echo "$technique $side $(tail -1 "$csv" | cut -d, -f6)" >> "$results"
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$results" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    technique, side, ms = line.split()
    runs.setdefault(technique, {"old": [], "new": []})[side].append(float(ms))
print(f"{'technique':<12} {'old ms':>10} {'new ms':>10} {'old / new':>10}   runs old | new")
for technique, sides in runs.items():
    old, new = statistics.median(sides["old"]), statistics.median(sides["new"])
    each = " ".join(f"{v:.0f}" for v in sides["old"]) + " | " + " ".join(f"{v:.0f}" for v in sides["new"])
    print(f"{technique:<12} {old:>10.1f} {new:>10.1f} {old / new:>10.2f}   {each}")
PY
