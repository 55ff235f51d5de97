#!/usr/bin/env bash
# The pictures of the metallic-roughness model (docs/lighting.md, issue 31), made with the
# project's own commands: scenes/pbr-models.json (the CC0 WaterBottle, metal and plastic balls,
# 300 coloured lights) as glTF's model shades it and with `"model_materials": "blinn-phong"`, the
# mapping every glTF material had before (the scene's own metallic-roughness balls and floor
# stay as they are), and scenes/studio.json (the built-in studio environment), into docs/images/.
#
# With HELMET=1 it also renders DamagedHelmet from ../shared/assets/gltf-pbr/ in both ways, into
# out/ only: its licence (CC BY-NC 4.0, "Battle Damaged Sci-fi Helmet - PBR" © 2016
# theblueturtle_, glTF rebuild © 2018 ctxwing) is non-commercial, so neither the model nor a
# picture of it enters the repository.
#
#   scripts/make-pbr-images.sh            HELMET=1 scripts/make-pbr-images.sh
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
ml=build/manylights
out=docs/images
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The same scene with the other mapping, beside it (paths inside stay relative to scenes/).
with_blinn_phong() {
  python3 - "$1" "$2" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["model_materials"] = "blinn-phong"
json.dump(scene, open(sys.argv[2], "w"))
PY
}
with_blinn_phong scenes/pbr-models.json scenes/.pbr-models-blinn-phong.json
trap 'rm -rf "$scratch" scenes/.pbr-models-blinn-phong.json' EXIT
$ml render scenes/pbr-models.json -o $out/pbr-models.png --size 640x400
$ml render scenes/.pbr-models-blinn-phong.json -o $out/pbr-models-blinn-phong.png --size 640x400
# The built-in studio environment behind a mirror, gold, copper, plastic and chalk ball (issue 42,
# docs/scene-format.md "environment").
$ml render scenes/studio.json -o $out/studio.png --size 640x360

if [ "${HELMET:-0}" = 1 ]; then
  helmet=$(realpath ../shared/assets/gltf-pbr/DamagedHelmet/DamagedHelmet.gltf)
  mkdir -p out
  cat >"$scratch/helmet.json" <<JSON
{
  "camera": {"eye": [0, 0.3, 3.2], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40, "near": 0.1, "far": 50},
  "ambient": [0.15, 0.15, 0.17],
  "directional": {"direction": [-1, -1, -1.5], "intensity": [0.6, 0.6, 0.6]},
  "light_sets": [{"count": 200, "seed": 5, "type": "point", "min": [-2.5, -1.5, -1], "max": [2.5, 1.5, 2],
                  "range": [0.8, 1.6], "intensity": [0.2, 0.6]}],
  "objects": [{"name": "helmet", "mesh": "$helmet"}]
}
JSON
  with_blinn_phong "$scratch/helmet.json" "$scratch/helmet-blinn-phong.json"
  $ml render "$scratch/helmet.json" -o out/damaged-helmet.png --size 640x480
  $ml render "$scratch/helmet-blinn-phong.json" -o out/damaged-helmet-blinn-phong.png --size 640x480
  echo "wrote out/damaged-helmet.png and out/damaged-helmet-blinn-phong.png (not for the repository)"
fi
