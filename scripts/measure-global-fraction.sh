#!/usr/bin/env bash
# The share of the grid a light must cover to go to the global list of tiled and clustered
# (render/culling/ClusterLists.h, kGlobalLightGridFraction): frames at several shares, set through
# MANYLIGHTS_GLOBAL_LIGHT_FRACTION (above 1: no global list but for unbounded lights), on scenes
# whose lights cover from a few tiles to all of the view: the courtyard at 64 and 256 lights
# (its ranges grow as the count falls) and the default scene, at 1280x720 without the display
# pass. Each round runs every share once per scene and technique before the next round, so
# that a machine whose load changes meets them alike; the table has the global lights, the
# pairs and the frame of each round (median of FRAMES after a warm-up), and the best round.
# Prints the machine and its load first.
#
#   scripts/measure-global-fraction.sh
#   FRACTIONS=0.25,0.5 ROUNDS=3 scripts/measure-global-fraction.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
fractions=${FRACTIONS:-0.125,0.25,0.5,0.75,2}
rounds=${ROUNDS:-2}
frames=${FRAMES:-3}
size=${SIZE:-1280x720}
out=out/global-fraction
rm -rf "$out"
mkdir -p "$out"
scenes=("bench/courtyard.json:64" "bench/courtyard.json:256" ":256")
for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    file=${scene%%:*}
    lights=${scene##*:}
    for technique in clustered tiled; do
      for fraction in ${fractions//,/ }; do
        name="$(basename "${file:-default}" .json)-$lights-$technique-$fraction-$round"
        MANYLIGHTS_GLOBAL_LIGHT_FRACTION=$fraction LP_NUM_THREADS=${LP_NUM_THREADS:-2} "$ML" render $file \
          --lights "$lights" --size "$size" --technique "$technique" --classic --frames "$frames" \
          -o "$out/$name.png" --stats "$out/$name.json" >/dev/null
      done
    done
  done
  echo "round $round done, load average $(cut -d' ' -f1-3 /proc/loadavg)"
done
python3 - "$out" "$fractions" "$rounds" "${scenes[@]}" <<'PY'
import json, sys
out, fractions, rounds, scenes = sys.argv[1], sys.argv[2].split(","), int(sys.argv[3]), sys.argv[4:]
print(f"{'scene':<16} {'technique':<10} {'share':>6} {'global':>7} {'pairs':>9}  {'frame ms by round':<24} {'best':>7}")
for scene in scenes:
    file, lights = scene.split(":")
    label = (file.split("/")[-1].removesuffix(".json") if file else "default") + f" {lights}"
    for technique in ("clustered", "tiled"):
        for fraction in fractions:
            runs = [json.load(open(f"{out}/{label.replace(' ', '-')}-{technique}-{fraction}-{r}.json"))
                    for r in range(1, rounds + 1)]
            frames = [run["frame_ms"]["median"] for run in runs]
            print(f"{label:<16} {technique:<10} {fraction:>6} {runs[0]['global_lights']:7.0f} "
                  f"{runs[0]['cluster_pairs']:9,.0f}  {', '.join(f'{f:.0f}' for f in frames):<24} {min(frames):7.0f}")
PY
