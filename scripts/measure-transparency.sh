#!/usr/bin/env bash
# The cost of the transparency pass (docs/transparency.md) on scenes/glass.json, and on the
# same scene with its panes only: the opaque lighting pass, the transparent grid and the
# transparent draws (median of FRAMES, each on the clock it was timed on), and from one counted
# frame (--count-work) the transparent fragments (forward's transparent pairs over its lights,
# every light reaching every fragment there) with their share of the pixels, and the lights the
# technique evaluates per pixel, opaque and transparent (divide its transparent evaluations by
# forward's fragments for the lights per transparent fragment). Through scripts/lib/bench.py,
# which prints the machine and its load first; read the figures as ratios within one run.
#
#   scripts/measure-transparency.sh            SIZE=640x360 TECHNIQUE=tiled scripts/measure-transparency.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/lib/scene_variants.py drop-objects scenes/glass.json "$out/panes.json" drop
args="--techniques forward,${TECHNIQUE:-clustered} --size ${SIZE:-1280x720} --count-work --warmup 1"
scripts/lib/bench.py --rounds "${ROUNDS:-1}" --frames "${FRAMES:-3}" \
  --column lighting --column "transparency grid" --column "draws=transparency" \
  --column "forward's transparent fragments=work.transparent_light_evaluations / lights" \
  --column "their share of the pixels=work.transparent_light_evaluations / lights * pixels" \
  --column "opaque lights per pixel=work.light_evaluations / pixels" \
  --column "transparent lights per pixel=work.transparent_light_evaluations / pixels" \
  --case "panes and drops: scenes/glass.json $args" --case "panes only: $out/panes.json $args"
