#!/bin/sh
# Load time of scenes with many inline lights (docs/performance.md, "Loading many lights"):
# writes scenes of 100,000, 400,000 and 1,000,000 point lights to a temporary folder, renders
# each at 64x64 and prints the load_ms that --stats reports (read, parse, duplicate-key pass,
# validation), with the machine and its load. ML= runs another build.
set -eu
ML=${ML:-build/manylights}
COUNTS=${COUNTS:-100000 400000 1000000}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "machine: $(nproc) cores, $(uname -m); load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $COUNTS; do
    python3 - "$n" "$dir/lights-$n.json" <<'PY'
import json, sys
n = int(sys.argv[1])
lights = [{"type": "point", "pos": [i % 100, 1, i // 100 % 100], "intensity": [1, 1, 1], "range": 1}
          for i in range(n)]
json.dump({"lights": lights, "objects": [{"mesh": {"primitive": "plane", "size": [10, 10]}}]},
          open(sys.argv[2], "w"))
PY
    "$ML" render "$dir/lights-$n.json" -o "$dir/out.png" --size 64x64 --stats "$dir/stats.json"
    python3 -c "import json,sys; print('%8d lights: load_ms %.0f' % ($n, json.load(open(sys.argv[1]))['load_ms']))" \
        "$dir/stats.json"
done
