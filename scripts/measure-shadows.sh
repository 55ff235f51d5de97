#!/usr/bin/env bash
# The cost of shadows and of SSAO (the tables in docs/shadows.md).
# Usage: scripts/measure-shadows.sh [WxH] [frames] [technique]
#  1. The default scene (256 point lights) with --shadow-lights 0, 8, 32: the frame time with
#     the maps reused (a static scene: only the lookups cost) and rebuilt every frame
#     (--rebuild-shadows: as when everything moves).
#  2. tests/scenes/shadows_and_ssao.json with the directional light's shadows and SSAO off and
#     on, one at a time.
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1280x720}
frames=${2:-5}
technique=${3:-clustered}
make build >/dev/null
ml=build/manylights
mkdir -p out/measure-shadows
summary() {  # label, stats file
  python3 - "$1" "$2" <<'PY'
import json, sys
stats = json.load(open(sys.argv[2]))
shadow_ms = sum(p["wall_ms"] for p in stats["passes"] if p["name"].startswith("shadow"))
ssao_ms = sum(p["wall_ms"] for p in stats["passes"] if p["name"] == "ssao")
print(f"{sys.argv[1]:<34} frame_ms {stats['frame_ms']['median']:9.1f}   shadow passes {shadow_ms:8.1f} ms   ssao pass {ssao_ms:6.1f} ms")
PY
}
for n in 0 8 32; do
  for mode in reused rebuilt; do
    extra=()
    [ "$mode" = rebuilt ] && extra=(--rebuild-shadows)
    stats=out/measure-shadows/default-$n-$mode.json
    $ml render -o out/measure-shadows/default-$n-$mode.png --size "$size" --technique "$technique" \
      --frames "$frames" --shadow-lights "$n" "${extra[@]}" --stats "$stats"
    summary "default, --shadow-lights $n, $mode" "$stats"
  done
done
scripts/shadow-scene-variants.py tests/scenes/shadows_and_ssao.json out/measure-shadows/scenes
for variant in plain shadows ssao both; do
  for mode in reused rebuilt; do
    extra=()
    [ "$mode" = rebuilt ] && extra=(--rebuild-shadows)
    stats=out/measure-shadows/$variant-$mode.json
    $ml render out/measure-shadows/scenes/$variant.json -o out/measure-shadows/$variant-$mode.png --size "$size" \
      --technique "$technique" --frames "$frames" "${extra[@]}" --stats "$stats"
    summary "shadows_and_ssao: $variant, $mode" "$stats"
  done
done
