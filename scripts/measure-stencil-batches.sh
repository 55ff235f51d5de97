#!/usr/bin/env bash
# The stencil technique's GL calls per light and its batches (render/volumes/StencilBatches.h,
# issue 41), with its frame and lighting pass, on the courtyard at 1280x720 at 4,096 and 65,536
# lights (LIGHTS= sets the counts), the median of FRAMES frames (render). OLD=<binary> runs another
# build as well, interleaved, the order swapped every other round: its `gl_calls` are there only
# if it counts them (gl/CallTally.h). The calls are exact and the same on every run; the times
# are llvmpipe's on a shared machine. Prints the machine and its load first and last.
#
#   scripts/measure-stencil-batches.sh
#   OLD=/tmp/manylights-per-light ROUNDS=2 scripts/measure-stencil-batches.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
lights=${LIGHTS:-4096 65536}
rounds=${ROUNDS:-1}
frames=${FRAMES:-3}
size=${SIZE:-1280x720}
out=out/stencil-batches
mkdir -p "$out"
binaries=("$ML")
[ -n "${OLD:-}" ] && binaries+=("$OLD")
for round in $(seq "$rounds"); do
  order=("${binaries[@]}")
  [ $((round % 2)) = 0 ] && [ ${#binaries[@]} = 2 ] && order=("${binaries[1]}" "${binaries[0]}")
  for n in $lights; do
    for binary in "${order[@]}"; do
      "$binary" render bench/courtyard.json --lights "$n" --technique stencil --size "$size" --frames "$frames" \
        --classic --stats "$out/stats.json" -o "$out/stencil.png"
      python3 - "$out/stats.json" "$round" "$n" "$binary" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
lighting = next(p for p in stats["passes"] if p["name"] == "lighting")
def field(name, form):
    return format(stats[name], form) if name in stats else "-"
print(f"round {sys.argv[2]}: {int(sys.argv[3]):>6,} lights, {sys.argv[4]}: gl_calls {field('gl_calls', ',.0f')}, "
      f"per light {field('gl_calls_per_light', '.2f')}, batches {field('stencil_batches', ',.0f')}, "
      f"frame {stats['frame_ms']['median']:.0f} ms, lighting {lighting['wall_ms']:.0f} ms")
PY
    done
  done
done
echo "machine after: load average $(cut -d' ' -f1-3 /proc/loadavg)"
