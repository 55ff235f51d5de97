#!/usr/bin/env bash
# What millions of lights cost before the first frame (docs/performance.md, "Millions of lights:
# start-up and memory"): bench/courtyard.json at each count, clustered at 64x36 (so that the
# frame is small beside the rest), and --stats' lights_ms (generating the light sets),
# renderer_ms (the scene on the GPU: the lights in spatial order, packed and uploaded, the
# technique's programs), their sum, the frame, clustered's gpu_memory_bytes and the process's
# peak resident memory. Prints the machine and its load first.
#
#   scripts/measure-startup.sh
#   COUNTS="1048576 16777216" scripts/measure-startup.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
counts=${COUNTS:-1048576 4194304 16777216}
out=out/startup
mkdir -p "$out"
for n in $counts; do
  /usr/bin/time -f "%M" -o "$out/rss.txt" "$ML" render bench/courtyard.json --lights "$n" --size 64x36 \
    --technique clustered -o "$out/frame.png" --stats "$out/stats.json"
  python3 - "$out/stats.json" "$n" "$(cat "$out/rss.txt")" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
n, rss_kb = int(sys.argv[2]), int(sys.argv[3])
loaded = s["lights_ms"] + s["renderer_ms"]
print(f"{n:>9} lights: lights {s['lights_ms'] / 1000:5.1f} s + renderer {s['renderer_ms'] / 1000:5.1f} s"
      f" = {loaded / 1000:5.1f} s; frame {s['frame_ms']['median'] / 1000:5.2f} s;"
      f" gpu_memory {s['gpu_memory_bytes'] / 2**20:7.1f} MiB ({s['gpu_memory_bytes'] / n:5.1f} B a light);"
      f" peak resident {rss_kb / 2**20:5.2f} GiB ({rss_kb * 1024 / n:5.0f} B a light)")
PY
done
