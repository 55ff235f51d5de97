#!/usr/bin/env bash
# Frame time of every technique on the animated default scene (the table in docs/viewer.md):
# each technique renders the scene at a mid-animation time, --frames after one warm-up.
# Usage: scripts/measure-animated.sh [WxH] [frames] [time]
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1280x720}
frames=${2:-5}
time=${3:-2.5}
make build >/dev/null
mkdir -p out
printf '%-12s %10s %10s  %s\n' technique median_ms min_ms 'passes (median wall ms)'
for technique in forward deferred volumes stencil tiled-quads tiled clustered; do
  build/manylights render -o "out/animated-$technique.png" --size "$size" --technique "$technique" \
    --time "$time" --frames "$frames" --stats "out/animated-$technique.json"
  python3 - "$technique" "out/animated-$technique.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[2]))
passes = ", ".join(f"{p['name']} {p['wall_ms']:.1f}" for p in stats["passes"])
print(f"{sys.argv[1]:<12} {stats['frame_ms']['median']:10.1f} {stats['frame_ms']['min']:10.1f}  {passes}")
PY
done
echo "device: $(python3 -c 'import json,sys; print(json.load(open("out/animated-forward.json"))["device"])')"
