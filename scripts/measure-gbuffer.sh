#!/usr/bin/env bash
# Bytes per pixel and lighting-pass time of the two G-buffer layouts (the table in
# docs/gbuffer.md): deferred and clustered on the default scene, with its own lights and with
# none (then the lighting pass is little more than reading the G-buffer); the layouts
# interleaved (scripts/lib/bench.py), and seed / compact.
# Usage: scripts/measure-gbuffer.sh [WxH] [frames]   (ML=, ROUNDS=, BENCH_ARGS=: docs/performance.md)
set -euo pipefail
cd "$(dirname "$0")/.."
args="--techniques deferred,clustered --size ${1:-1280x720} --warmup 1"
cases=()
for lights in scene 0; do
  for layout in seed compact; do
    extra=
    [ "$lights" = 0 ] && extra="--lights 0"
    cases+=(--case "$layout/$lights lights: --gbuffer $layout $args $extra")
  done
done
exec scripts/lib/bench.py --frames "${2:-3}" --digits 2 --column geometry --column lighting --compare "${cases[@]}"
