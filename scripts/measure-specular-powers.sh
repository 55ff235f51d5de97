#!/usr/bin/env bash
# The specular power by multiplication against pow() (shaders/lib/specular_power.glsl): the
# courtyard (bench/courtyard.json, shininess 16, 32, 48 and 64 on its four specular materials)
# with those four set to other integer shininesses, each scene run as it is (multiplications,
# where render/programs/LightingPrograms.h's limits allow) and with every shininess 0.001 larger (no
# longer integers: pow(), whose cost does not depend on the exponent); the last case is over the
# multiplications' budget, so both take pow(). `clustered`'s lighting pass, median of FRAMES
# frames, the cases interleaved REPS (or ROUNDS) times (scripts/lib/bench.py), and integers / pow.
# Prints the machine and its load first; read the figures as ratios within one run.
#
#   scripts/measure-specular-powers.sh            TECHNIQUE=deferred SIZE=640x360 scripts/measure-specular-powers.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
args="--techniques ${TECHNIQUE:-clustered} --size ${SIZE:-1280x720} --warmup 1"
# Each case: a name and the shininesses that replace 16, 32, 48 and 64.
cases=()
for case in "as-is 16 32 48 64" "all-16 16 16 16 16" "all-255 255 255 255 255" "all-1023 1023 1023 1023 1023" \
  "over-the-budget 127 191 223 255"; do
  read -r name a b c d <<<"$case"
  for kind in integers pow; do
    offset=0
    [ "$kind" = pow ] && offset=0.001
    scripts/lib/scene_variants.py shininess bench/courtyard.json "$out/$name-$kind.json" --offset "$offset" \
      --replace "16=$a,32=$b,48=$c,64=$d"
    cases+=(--case "$kind/$name $a $b $c $d: $out/$name-$kind.json $args")
  done
done
scripts/lib/bench.py --rounds "${REPS:-${ROUNDS:-2}}" --frames "${FRAMES:-3}" --column lighting --compare "${cases[@]}"
