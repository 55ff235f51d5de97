#!/usr/bin/env bash
# Median frame time and per-pass fragment invocations of each technique on the default
# scene (the table in docs/techniques.md). Usage: scripts/measure-techniques.sh [WxH] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1280x720}
frames=${2:-5}
make build >/dev/null
mkdir -p out
printf '%-10s %12s  %s\n' technique frame_ms 'passes (wall ms, fragment invocations)'
for technique in forward deferred; do
  build/manylights render -o out/measure-$technique.png --size "$size" --technique "$technique" \
    --frames "$frames" --stats out/measure-$technique.json
  python3 - "$technique" out/measure-$technique.json <<'PY'
import json, sys
stats = json.load(open(sys.argv[2]))
passes = ", ".join(f"{p['name']} {p['wall_ms']:.0f} ms {p['fragment_invocations']}" for p in stats["passes"])
print(f"{sys.argv[1]:<10} {stats['frame_ms']['median']:12.1f}  {passes}")
PY
done
