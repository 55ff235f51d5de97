#!/usr/bin/env bash
# The cost of shadowing every light through the shadow-page pool (issue 47, docs/shadows.md,
# "What it costs"), through scripts/lib/bench.py:
#  1. bench/courtyard.json at 4,096 lights (LIGHTS=), clustered (TECHNIQUE=), 1280x720 (SIZE=):
#     unshadowed; every light shadowed with its pages cached (a still scene: the frame pays the
#     lookups only); and every page marked and drawn every frame (--rebuild-shadows, as when
#     everything moves). The shadow passes ("shadow marks", "shadow clears" and "shadow pages")
#     and the lighting are columns, the lighting also per (pixel, light) pair; the ratios are
#     read against the unshadowed row of the same round.
#  2. render --stats of a frame that marks and draws every page (--rebuild-shadows) at 1,024 to 65,536 lights (COUNTS=), every light
#     shadowed: the faces, the pages they hold, the levels a short pool took, and the GL calls
#     of the shadow work (shadow_gl_calls: they must not grow with the light count).
# Prints the machine and its load first. ML=, ROUNDS=, FRAMES= as docs/performance.md says.
#
#   scripts/measure-shadow-pool.sh          ROUNDS=3 scripts/measure-shadow-pool.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-1280x720}
lights=${LIGHTS:-4096}
technique=${TECHNIQUE:-clustered}
# --count-work: a separate counting frame gives the (pixel, light) pairs the lighting evaluated
# (the same with or without shadows), so that the lighting's cost reads per pair: the shadowed
# rows' figure less the unshadowed one's is the lookup's cost per pair.
common="bench/courtyard.json --techniques $technique --lights $lights --size $size --count-work"
scripts/lib/bench.py --frames "${FRAMES:-3}" \
  --column "shadow passes=shadow*" --column lighting \
  --column "lighting ns a pair=lighting * 1000000 / work.light_evaluations" \
  --column "pairs=work.light_evaluations" \
  --column "faces=stat.shadow_faces" --column "pages=stat.shadow_pages_used" \
  --case "unshadowed: $common" \
  --case "all shadowed, cached: $common --shadow-lights all" \
  --case "all shadowed, rebuilt: $common --shadow-lights all --rebuild-shadows"
cases=()
for n in ${COUNTS:-1024 4096 16384 65536}; do
  cases+=(--case "first frame/$n: render bench/courtyard.json --technique $technique --lights $n --size $size --shadow-lights all --rebuild-shadows")
done
scripts/lib/bench.py --frames 1 --quiet-rounds \
  --column "faces=stat.shadow_faces" --column "lights with faces=stat.shadow_lights_with_faces" \
  --column "pages=stat.shadow_pages_used" --column "levels lowered=stat.shadow_levels_lowered" \
  --column "faces dropped=stat.shadow_faces_dropped" --column "shadow GL calls=stat.shadow_gl_calls" \
  --column "caster triangles=stat.shadow_caster_triangles" --column "shadow marks" --column "shadow clears" \
  --column "shadow pages" "${cases[@]}"
