#!/usr/bin/env bash
# One build against another on the same machine in one session: every technique's median
# frame on a scene and the median wall time of one of its passes (PASS, default lighting),
# the two builds interleaved per technique (A B A B with REPS=2), and the ratios old / new.
# A change's before and after: OLD is the build of the commit before it. For issue 12's courtyard target ("every technique at least 2x faster than
# the docs' table"): build the table's commit elsewhere and pass its binary as OLD.
#
#   OLD=/tmp/table/build/manylights scripts/measure-speedup.sh
#   OLD=... SCENE=default LIGHTS=4096 TECHNIQUES=clustered scripts/measure-speedup.sh   (the built-in scene)
#   OLD=... SCENE=bench/courtyard.json LIGHTS=4096 SIZE=1280x720 TECHNIQUES=clustered,tiled REPS=2 scripts/measure-speedup.sh
#
# Slow techniques (forward, deferred: seconds per frame) get SLOW_FRAMES frames (default 1),
# the others FRAMES (default 3), each after one warm-up frame. Prints the machine and its load
# first; read the ratios within one run.
set -euo pipefail
cd "$(dirname "$0")/.."
: "${OLD:?OLD=the manylights binary of the other build}"
scene=${SCENE:-bench/courtyard.json}
scene_args=()
[ "$scene" = default ] || scene_args=("$scene")
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
      "$binary" bench "${scene_args[@]}" --techniques "$technique" --lights "$lights" --size "$size" --frames "$frames" \
        --warmup 1 --csv "$csv" >/dev/null
      python3 - "$csv" "$technique" "$side" "${PASS:-lighting}" >> "$results" <<'PY'
import csv, sys
row = list(csv.DictReader(open(sys.argv[1])))[-1]
passes = {p.split(":")[0]: p.split(":")[1] for p in row["passes"].split(";")}
print(sys.argv[2], sys.argv[3], row["frame_ms_median"], passes.get(sys.argv[4], "nan"))
PY
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$results" "${PASS:-lighting}" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    technique, side, frame, pass_ms = line.split()
    runs.setdefault(technique, {"old": [], "new": []})[side].append((float(frame), float(pass_ms)))
name = sys.argv[2]
print(f"{'technique':<12} {'old ms':>9} {'new ms':>9} {'old/new':>8}   {'old ' + name:>14} {'new ' + name:>14} {'old/new':>8}   frames old | new")
for technique, sides in runs.items():
    old = [statistics.median(v[i] for v in sides["old"]) for i in (0, 1)]
    new = [statistics.median(v[i] for v in sides["new"]) for i in (0, 1)]
    each = " ".join(f"{v[0]:.0f}" for v in sides["old"]) + " | " + " ".join(f"{v[0]:.0f}" for v in sides["new"])
    print(f"{technique:<12} {old[0]:>9.1f} {new[0]:>9.1f} {old[0] / new[0]:>8.2f}   "
          f"{old[1]:>14.1f} {new[1]:>14.1f} {old[1] / new[1]:>8.2f}   {each}")
PY
