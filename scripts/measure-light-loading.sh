#!/usr/bin/env bash
# Load time of scenes with many inline lights (docs/performance.md, "Loading many lights"):
# writes scenes of 100,000, 400,000 and 1,000,000 point lights to a temporary folder, renders
# each at 64x64 and prints the load_ms that --stats reports (read, parse, duplicate-key pass,
# validation), with the machine and its load (scripts/lib/bench.py). ML= runs another build.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cases=()
for n in ${COUNTS:-100000 400000 1000000}; do
  scripts/lib/scene_variants.py light-grid "$n" "$dir/lights-$n.json"
  cases+=(--case "$n inline lights: render $dir/lights-$n.json --size 64x64")
done
scripts/lib/bench.py --rounds "${ROUNDS:-1}" --digits 0 --column "load_ms=stat.load_ms" "${cases[@]}"
