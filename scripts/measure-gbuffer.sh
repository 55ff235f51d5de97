#!/usr/bin/env bash
# Bytes per pixel and lighting-pass time of the two G-buffer layouts (the table in
# docs/gbuffer.md): deferred and clustered on the default scene, with its own lights and with
# none (then the lighting pass is little more than reading the G-buffer).
# Usage: scripts/measure-gbuffer.sh [WxH] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1280x720}
frames=${2:-3}
make build >/dev/null
mkdir -p out
printf '%-10s %-8s %-7s %12s %12s\n' technique layout lights geometry_ms lighting_ms
for technique in deferred clustered; do
  for lights in scene 0; do
    for layout in seed compact; do
      extra=()
      [ "$lights" = 0 ] && extra=(--lights 0)
      stats=out/gbuffer-$technique-$layout-$lights.json
      build/manylights render -o out/gbuffer-$technique-$layout.png --size "$size" --technique "$technique" \
        --gbuffer "$layout" --frames "$frames" --stats "$stats" "${extra[@]}"
      python3 - "$technique" "$layout" "$lights" "$stats" <<'PY'
import json, sys
stats = json.load(open(sys.argv[4]))
# wall_ms: llvmpipe's GL_TIME_ELAPSED misses most of a pass of many draws (docs/cli.md).
ms = {p["name"]: p["wall_ms"] for p in stats["passes"]}
print(f"{sys.argv[1]:<10} {sys.argv[2]:<8} {sys.argv[3]:<7} {ms.get('geometry', 0):12.2f} {ms.get('lighting', 0):12.2f}")
PY
    done
  done
done
