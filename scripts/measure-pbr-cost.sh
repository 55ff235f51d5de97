#!/usr/bin/env bash
# The per-pair cost of the metallic-roughness model against Blinn-Phong's (issue 31,
# docs/performance.md): the courtyard (bench/courtyard.json) as it is (Blinn-Phong, its four
# integer shininesses raised by multiplications), with those shininesses 0.001 larger (pow()),
# and with every material converted to metallic-roughness (base_color = diffuse, metallic 0,
# roughness (2 / (s + 2))^(1/4), the roughness whose Blinn-Phong exponent is s; the iron,
# whose specular outweighs its diffuse, a metal of base colour its specular). `clustered`'s
# lighting pass, median wall ms of FRAMES frames, with the scene's lights and with none (what the
# pass costs without pairs: the G-buffer read, the global terms); the per-pair cost is
# (with − without) / the pass's light evaluations (--count-work, the same for all three scenes).
# The cases alternate, REPS times. Prints the machine and its load first; read the figures as
# ratios within one run.
#
#   scripts/measure-pbr-cost.sh            TECHNIQUE=deferred SIZE=640x360 LIGHTS=256 scripts/measure-pbr-cost.sh
set -euo pipefail
cd "$(dirname "$0")/.."
technique=${TECHNIQUE:-clustered}
size=${SIZE:-1280x720}
frames=${FRAMES:-3}
reps=${REPS:-2}
lights=${LIGHTS:-1024}
source scripts/measure-common.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
scene = json.load(open("bench/courtyard.json"))
json.dump(scene, open(f"{out}/blinn-phong.json", "w"))
pow_scene = json.loads(json.dumps(scene))
for material in pow_scene["materials"].values():
    if "shininess" in material:
        material["shininess"] += 0.001
json.dump(pow_scene, open(f"{out}/blinn-phong-pow.json", "w"))
for name, material in scene["materials"].items():
    diffuse = material.get("diffuse", [0.8, 0.8, 0.8])
    specular = material.get("specular", [0, 0, 0])
    shininess = material.get("shininess", 32)
    metal = max(specular) > max(diffuse)
    scene["materials"][name] = {
        "base_color": specular if metal else diffuse,
        "metallic": 1 if metal else 0,
        "roughness": round((2.0 / (shininess + 2.0)) ** 0.25, 4) if max(specular) > 0 else 1,
    }
json.dump(scene, open(f"{out}/metallic-roughness.json", "w"))
PY
lighting_ms() {
  python3 -c "import json, sys; d = json.load(open(sys.argv[1]))
print(next(p['wall_ms'] for p in d['passes'] if p['name'] == 'lighting'))" "$1"
}
cases=(blinn-phong blinn-phong-pow metallic-roughness)
declare -A with without
for ((rep = 0; rep < reps; ++rep)); do
  for name in "${cases[@]}"; do
    "$ML" render "$out/$name.json" -o "$out/image.png" --size "$size" --technique "$technique" --lights "$lights" \
      --frames "$frames" --stats "$out/stats.json" >/dev/null
    with[$name]+="$(lighting_ms "$out/stats.json") "
    "$ML" render "$out/$name.json" -o "$out/image.png" --size "$size" --technique "$technique" --lights 0 \
      --frames "$frames" --stats "$out/stats.json" >/dev/null
    without[$name]+="$(lighting_ms "$out/stats.json") "
  done
done
"$ML" render "$out/blinn-phong.json" -o "$out/image.png" --size "$size" --technique "$technique" --lights "$lights" \
  --count-work --stats "$out/work.json" >/dev/null
evaluations=$(python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['light_evaluations'])" "$out/work.json")
echo "$technique, bench/courtyard.json at $lights lights, $size: lighting pass, median wall ms; $evaluations light evaluations"
printf '%-22s %-16s %-16s %-14s %s\n' "materials" "with lights" "without" "ns per pair" "/ Blinn-Phong's"
ordered=("$evaluations" "${cases[@]}" --)
for name in "${cases[@]}"; do ordered+=("${with[$name]}"); done
ordered+=(--)
for name in "${cases[@]}"; do ordered+=("${without[$name]}"); done
python3 - "${ordered[@]}" <<'PY'
import statistics, sys
args = sys.argv[1:]
evaluations = float(args[0])
first, second = args.index("--"), len(args) - 1 - args[::-1].index("--")
names, withs, withouts = args[1:first], args[first + 1:second], args[second + 1:]
spread = lambda xs: f"{min(xs):.1f}-{max(xs):.1f}"
per_pair = {}
for name, w, wo in zip(names, withs, withouts):
    w, wo = list(map(float, w.split())), list(map(float, wo.split()))
    per_pair[name] = (statistics.median(w) - statistics.median(wo)) * 1e6 / evaluations
    print(f"{name:<22} {spread(w):<16} {spread(wo):<16} {per_pair[name]:<14.2f} "
          f"{per_pair[name] / per_pair['blinn-phong']:.2f}")
PY
