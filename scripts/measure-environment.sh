#!/usr/bin/env bash
# What the environment costs (issue 42, docs/performance.md "The environment"): per frame,
# `clustered` at 1280x720 on the courtyard (bench/courtyard.json) at 1,024 lights and on
# scenes/pbr-models.json (whose metallic-roughness materials make the prefiltered lookup), each
# without its `environment` and with builtin:studio (not shown as the background, so that only
# the lighting differs); the median frame and lighting pass of FRAMES frames, the cases
# interleaved REPS (or ROUNDS) times, and without / with. At load, environment_ms of a 1024x512
# .hdr map (made here: smooth noise and a few bright patches): reading, harmonics, upload and
# prefiltering until the GPU finished (render --stats). Prints the machine and its load first
# (scripts/lib/bench.py); read the per-frame figures as ratios within one run.
#
#   scripts/measure-environment.sh            FRAMES=5 REPS=3 SIZE=640x360 scripts/measure-environment.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-1280x720}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/lib/scene_variants.py environment bench/courtyard.json "$out/courtyard-without.json" "$out/courtyard-with.json"
scripts/lib/scene_variants.py environment scenes/pbr-models.json "$out/pbr-models-without.json" \
  "$out/pbr-models-with.json"
scripts/lib/scene_variants.py hdr-map "$out/map-1024.hdr"
echo '{"environment": {"map": "map-1024.hdr"}}' >"$out/map-1024.json"
args="--techniques clustered --size $size --warmup 1"
scripts/lib/bench.py --rounds "${REPS:-${ROUNDS:-2}}" --frames "${FRAMES:-3}" --column lighting \
  --column "environment_ms=stat.environment_ms" --compare \
  --case "without/courtyard: $out/courtyard-without.json --lights 1024 $args" \
  --case "with/courtyard: $out/courtyard-with.json --lights 1024 $args" \
  --case "without/pbr-models: $out/pbr-models-without.json $args" \
  --case "with/pbr-models: $out/pbr-models-with.json $args" \
  --case "a 1024x512 .hdr map: render $out/map-1024.json --size 64x64"
