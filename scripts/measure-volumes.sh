#!/usr/bin/env bash
# Median frame time, lighting-pass wall time and fragment invocations, and light
# evaluations against in-range pairs, of deferred, volumes and stencil on the default scene
# at 1280x720 with 256, 1024 and 4096 lights (the table in docs/techniques.md).
# Usage: scripts/measure-volumes.sh [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-3}
make build >/dev/null
mkdir -p out
printf '%-9s %6s %10s %12s %14s %14s %12s\n' technique lights frame_ms lighting_ms invocations evaluations in_range
for lights in 256 1024 4096; do
  for technique in deferred volumes stencil; do
    base=out/volumes-$technique-$lights
    build/manylights render -o $base.png --technique $technique --lights $lights --frames "$frames" --stats $base.json
    build/manylights render -o $base-count.png --technique $technique --lights $lights --count-work \
      --stats $base-count.json
    python3 - $technique $lights $base.json $base-count.json <<'PY'
import json, sys
timed, counted = json.load(open(sys.argv[3])), json.load(open(sys.argv[4]))
lighting = next(p for p in timed["passes"] if p["name"] == "lighting")
print(f"{sys.argv[1]:<9} {sys.argv[2]:>6} {timed['frame_ms']['median']:10.1f} {lighting['wall_ms']:12.1f} "
      f"{lighting['fragment_invocations']:>14} {counted['light_evaluations']:>14} {counted['in_range_pairs']:>12}")
PY
  done
done
