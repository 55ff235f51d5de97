#!/usr/bin/env bash
# The cost of shadows and of SSAO (the tables in docs/shadows.md), through scripts/lib/bench.py
# (render --stats: only render has --rebuild-shadows); the shadow passes together and the SSAO
# pass, each on the clock it was timed on.
# Usage: scripts/measure-shadows.sh [WxH] [frames] [technique]   (ML=, ROUNDS=, BENCH_ARGS=:
# docs/performance.md)
#  1. The default scene (256 point lights) with --shadow-lights 0, 8, 32: the frame time with
#     the maps reused (a static scene: only the lookups cost) and rebuilt every frame
#     (--rebuild-shadows: as when everything moves).
#  2. tests/scenes/shadows_and_ssao.json with the directional light's shadows and SSAO off and
#     on, one at a time.
set -euo pipefail
cd "$(dirname "$0")/.."
args="--size ${1:-1280x720} --technique ${3:-clustered}"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/shadow-scene-variants.py tests/scenes/shadows_and_ssao.json "$out"
cases=()
for n in 0 8 32; do
  cases+=(--case "default --shadow-lights $n/reused: render $args --shadow-lights $n")
  cases+=(--case "default --shadow-lights $n/rebuilt: render $args --shadow-lights $n --rebuild-shadows")
done
for variant in plain shadows ssao both; do
  cases+=(--case "shadows_and_ssao $variant/reused: render $out/$variant.json $args")
  cases+=(--case "shadows_and_ssao $variant/rebuilt: render $out/$variant.json $args --rebuild-shadows")
done
scripts/lib/bench.py --frames "${2:-5}" --column "shadow passes=shadow*" --column ssao "${cases[@]}"
