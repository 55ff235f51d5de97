#!/usr/bin/env bash
# The specular power by multiplication against pow() (shaders/lib/specular_power.glsl): the
# courtyard (bench/courtyard.json, shininess 16, 32, 48 and 64 on its four specular materials)
# with those four set to other integer shininesses, each scene run as it is (multiplications,
# where render/programs/LightingPrograms.h's limits allow) and with every shininess 0.001 larger (no
# longer integers: pow(), whose cost does not depend on the exponent); the last case is over the
# multiplications' budget, so both take pow(). `clustered`'s lighting
# pass, median wall ms of FRAMES frames, the two alternated REPS times. Prints the machine and
# its load first; read the figures as ratios within one run.
#
#   scripts/measure-specular-powers.sh            TECHNIQUE=deferred SIZE=640x360 scripts/measure-specular-powers.sh
set -euo pipefail
cd "$(dirname "$0")/.."
technique=${TECHNIQUE:-clustered}
size=${SIZE:-1280x720}
frames=${FRAMES:-3}
reps=${REPS:-2}
source scripts/measure-common.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Each case: a name and the shininesses that replace 16, 32, 48 and 64.
cases=("as-is 16 32 48 64" "all-16 16 16 16 16" "all-255 255 255 255 255" "all-1023 1023 1023 1023 1023"
       "over-the-budget 127 191 223 255")
for case in "${cases[@]}"; do
  read -r -a words <<<"$case"
  python3 - "$out" "${words[@]}" <<'PY'
import json, sys
out, name, *values = sys.argv[1:]
replace = dict(zip([16, 32, 48, 64], map(int, values)))
for kind, offset in (("chains", 0.0), ("pow", 0.001)):
    scene = json.load(open("bench/courtyard.json"))
    for material in scene["materials"].values():
        if "shininess" in material:
            material["shininess"] = replace[material["shininess"]] + offset
    json.dump(scene, open(f"{out}/{name}-{kind}.json", "w"))
PY
done
echo "$technique, bench/courtyard.json with its shininesses replaced, $size: lighting pass, median wall ms"
printf '%-36s %-14s %-14s %s\n' "case: shininesses" "as integers" "+0.001 (pow)" "integers / pow"
for case in "${cases[@]}"; do
  name=${case%% *}
  declare -A runs=([chains]="" [pow]="")
  for ((rep = 0; rep < reps; ++rep)); do
    for kind in chains pow; do
      "$ML" render "$out/$name-$kind.json" -o "$out/image.png" --size "$size" --technique "$technique" \
        --frames "$frames" --stats "$out/stats.json" >/dev/null
      runs[$kind]+="$(python3 -c "import json, sys; d = json.load(open(sys.argv[1]))
print(next(p['wall_ms'] for p in d['passes'] if p['name'] == 'lighting'))" "$out/stats.json") "
    done
  done
  python3 - "$case" "${runs[chains]}" "${runs[pow]}" <<'PY'
import statistics, sys
case, chains, pows = sys.argv[1], list(map(float, sys.argv[2].split())), list(map(float, sys.argv[3].split()))
spread = lambda xs: f"{min(xs):.1f}-{max(xs):.1f}"
name, *values = case.split()
print(f"{name + ': ' + ' '.join(values):<36} {spread(chains):<14} {spread(pows):<14} {statistics.median(chains) / statistics.median(pows):.2f}")
PY
done
