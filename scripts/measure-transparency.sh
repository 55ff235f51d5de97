#!/usr/bin/env bash
# The cost of the transparency pass (docs/transparency.md) on scenes/glass.json, and on the
# same scene with its panes only: the opaque lighting pass, the transparent grid and the
# transparent draws (median wall ms of `render --frames`), the transparent fragments (forward's
# transparent pairs over its lights, from --count-work) and what the draws would cost at the
# opaque pass's cost per pixel (its share of covered pixels), and the lights the technique
# evaluates per transparent fragment and per opaque pixel. Prints the machine and its load
# first; read the figures as ratios within one run.
#
#   scripts/measure-transparency.sh            SIZE=640x360 TECHNIQUE=tiled scripts/measure-transparency.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-1280x720}
technique=${TECHNIQUE:-clustered}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
source scripts/measure-common.sh
python3 - "$out" <<'PY'
import json, sys
scene = json.load(open("scenes/glass.json"))
scene["objects"] = [o for o in scene["objects"] if not o["name"].startswith("drop")]
json.dump(scene, open(f"{sys.argv[1]}/panes.json", "w"))
PY
for variant in whole panes; do
  scene=scenes/glass.json
  [ "$variant" = panes ] && scene="$out/panes.json"
  "$ML" render "$scene" -o "$out/$variant.png" --size "$size" --technique "$technique" --frames "${FRAMES:-3}" \
    --stats "$out/$variant-timed.json"
  "$ML" render "$scene" -o "$out/$variant-forward.png" --size "$size" --technique forward --count-work \
    --stats "$out/$variant-counted.json"
  "$ML" render "$scene" -o "$out/$variant-culled.png" --size "$size" --technique "$technique" --count-work \
    --stats "$out/$variant-culled.json"
done
python3 - "$out" "$technique" "$size" <<'PY'
import json, sys
out, technique, size = sys.argv[1:]
width, height = map(int, size.split("x"))
print(f"\n{technique}, scenes/glass.json, {size}: median wall ms")
for variant, label in (("whole", "panes and drops"), ("panes", "panes only")):
    timed = json.load(open(f"{out}/{variant}-timed.json"))
    counted = json.load(open(f"{out}/{variant}-counted.json"))
    passes = {p["name"]: p for p in timed["passes"]}
    lighting = passes["lighting"]["wall_ms"]
    grid = passes.get("transparency grid", {"wall_ms": 0.0})["wall_ms"]
    draws = passes["transparency"]["wall_ms"]
    fragments = counted["transparent_light_evaluations"] // counted["lights"]
    share = fragments / (width * height)
    print(f"  {label:16s} opaque lighting {lighting:7.1f}  transparency grid {grid:6.1f}  draws {draws:7.1f}"
          f"  for {fragments} fragments ({100 * share:.0f} % of the pixels: the share is"
          f" {share * lighting:.1f} ms; draws {draws / (share * lighting):.1f}x it)")
    culled = json.load(open(f"{out}/{variant}-culled.json"))
    print(f"  {'':16s} lights evaluated per transparent fragment {culled['transparent_light_evaluations'] / fragments:.1f},"
          f" per opaque pixel {culled['light_evaluations'] / (width * height):.1f}")
PY
