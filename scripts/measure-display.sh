#!/usr/bin/env bash
# The cost of the display path (docs/display.md): the default scene at 1280x720 with
# `clustered`, timed by bench in the classic look (`--classic`: no display pass runs), in the
# default look (PBR Neutral and sRGB), with FXAA as well, and under AgX (the default until
# issue 48); prints each pass's median time, its share of the frame, and both passes' share
# together. The four run in turn, REPEAT (or ROUNDS) times,
# the order rotated (scripts/lib/bench.py). Prints the machine and its load first; read the
# figures as ratios within one run.
#
#   scripts/measure-display.sh                 SIZE=1920x1080 TECHNIQUE=deferred scripts/measure-display.sh
set -euo pipefail
cd "$(dirname "$0")/.."
args="--techniques ${TECHNIQUE:-clustered} --size ${SIZE:-1280x720}"
exec scripts/lib/bench.py --rounds "${REPEAT:-${ROUNDS:-1}}" --frames "${FRAMES:-5}" --warmup 1 \
  --column display --column fxaa --column "both=display + fxaa" \
  --column "display share=display / frame" --column "both share=display + fxaa / frame" \
  --case "classic (no pass runs): $args --classic" \
  --case "default (PBR Neutral, sRGB): $args" \
  --case "default and --aa fxaa: $args --aa fxaa" \
  --case "--tonemap agx (sRGB): $args --tonemap agx"
