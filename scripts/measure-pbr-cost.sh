#!/usr/bin/env bash
# The per-pair cost of the metallic-roughness model against Blinn-Phong's (issue 31,
# docs/performance.md): the courtyard (bench/courtyard.json) as it is (Blinn-Phong, its four
# integer shininesses raised by multiplications), with those shininesses 0.001 larger (pow()),
# and with every material converted to metallic-roughness (scripts/lib/scene_variants.py:
# base_color = diffuse, metallic 0, roughness (2 / (s + 2))^(1/4), the roughness whose
# Blinn-Phong exponent is s; the iron, whose specular outweighs its diffuse, a metal of base
# colour its specular). `clustered`'s lighting pass, median of FRAMES frames, with the scene's
# lights and with none (what the pass costs without pairs: the G-buffer read, the global terms);
# the per-pair cost is (with − without) / the pass's light evaluations (--count-work), and each
# against Blinn-Phong's. The cases interleave, REPS (or ROUNDS) times (scripts/lib/bench.py).
# Prints the machine and its load first; read the figures as ratios within one run.
#
#   scripts/measure-pbr-cost.sh            TECHNIQUE=deferred SIZE=640x360 LIGHTS=256 scripts/measure-pbr-cost.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cp bench/courtyard.json "$out/blinn-phong.json"
scripts/lib/scene_variants.py shininess bench/courtyard.json "$out/blinn-phong-pow.json" --offset 0.001
scripts/lib/scene_variants.py metallic-roughness bench/courtyard.json "$out/metallic-roughness.json"
args="--techniques ${TECHNIQUE:-clustered} --size ${SIZE:-1280x720} --lights 0,${LIGHTS:-1024} --count-work --warmup 1"
scripts/lib/bench.py --rounds "${REPS:-${ROUNDS:-2}}" --frames "${FRAMES:-3}" --per-pair lighting \
  --case "blinn-phong: $out/blinn-phong.json $args" \
  --case "blinn-phong-pow: $out/blinn-phong-pow.json $args" \
  --case "metallic-roughness: $out/metallic-roughness.json $args"
