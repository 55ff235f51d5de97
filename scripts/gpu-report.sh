#!/usr/bin/env bash
# The first measurements on a hardware GPU (issue 30), as one markdown report naming the
# device and the driver: `make test` on it, the light sweep at 1920x1080 (1,024 to 1,048,576
# lights, every technique within a time budget), the courtyard table of docs/performance.md
# (1280x720), the light lists from bit masks against sorted ones, and the LearnOpenGL
# comparison (../shared/peer/learnopengl-8.1/compare.sh).
#
# Usage: scripts/gpu-report.sh [--anyway] [--device N] [--out DIR]
#   --anyway    run on a software rasteriser too (llvmpipe); without it the script says that
#               there is no GPU here and stops (exit 1), as the figures would be llvmpipe's
#   --device N  the EGL device to measure (build/manylights devices lists them; default: the
#               renderer's own choice, hardware first)
#   --out DIR   where the report (DIR/gpu-report.md) and the raw outputs go (default out/gpu-report)
# Settings from the environment, for a quicker look:
#   SWEEP_LIGHTS=1024,4096,16384,65536,262144,1048576  SWEEP_SIZE=1920x1080
#   COURTYARD_LIGHTS=256,1024,4096,16384,65536  COURTYARD_SIZE=1280x720
#   FRAMES=5  BUDGET_MS=1000 (a technique's larger light counts are skipped once its median
#   frame passes this)  LEARNOPENGL_LIGHTS="32 128 512"  TESTS=1  MASKED_LISTS=1  LEARNOPENGL=1
#   (0 skips a part)
set -euo pipefail
cd "$(dirname "$0")/.."

anyway=0
device=()
out=out/gpu-report
while [ $# -gt 0 ]; do
  case "$1" in
    --anyway) anyway=1 ;;
    --device) device=(--device "$2"); shift ;;
    --out) out=$2; shift ;;
    *) echo "usage: scripts/gpu-report.sh [--anyway] [--device N] [--out DIR]" >&2; exit 2 ;;
  esac
  shift
done
sweep_lights=${SWEEP_LIGHTS:-1024,4096,16384,65536,262144,1048576}
sweep_size=${SWEEP_SIZE:-1920x1080}
courtyard_lights=${COURTYARD_LIGHTS:-256,1024,4096,16384,65536}
courtyard_size=${COURTYARD_SIZE:-1280x720}
frames=${FRAMES:-5}
budget=${BUDGET_MS:-1000}
learnopengl_lights=${LEARNOPENGL_LIGHTS:-32 128 512}
ml=build/manylights

make build >/dev/null
mkdir -p "$out"
devices=$("$ml" devices 2>&1 || true)
# What the renderer runs on with these options: its --stats name it.
"$ml" render -o "$out/probe.png" --size 64x36 --stats "$out/probe.json" "${device[@]}"
renderer=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["device"])' "$out/probe.json")
profile=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["driver_profile"])' "$out/probe.json")
if [ "$profile" = software ]; then
  echo "gpu-report: $renderer is a software rasteriser, not a GPU: nothing to report here" >&2
  if [ "$anyway" = 0 ]; then
    echo "gpu-report: on a GPU server pick its device (--device N; build/manylights devices lists them)," \
         "or run anyway with --anyway" >&2
    exit 1
  fi
fi

report=$out/gpu-report.md
{
  echo "# manylights on $renderer"
  echo
  echo "$(date -u +%Y-%m-%d), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)," \
       "driver profile \`$profile\`$([ "$profile" = software ] && echo ' (a software rasteriser: run with --anyway, not GPU figures)')."
  echo "Machine: $(nproc) CPU cores, $(uname -sr)."
  echo
  echo "## Devices (\`manylights devices\`)"
  echo
  echo '```'
  echo "$devices"
  echo '```'
} > "$report"

section() { printf '\n## %s\n\n' "$1" >> "$report"; }
fenced() { { echo '```'; cat "$1"; echo '```'; } >> "$report"; }

if [ "${TESTS:-1}" = 1 ]; then
  section "make test"
  start=$(date +%s)
  if make test > "$out/test.log" 2>&1; then result=passed; else result=FAILED; fi
  echo "$result in $(($(date +%s) - start)) s (log: $out/test.log)." >> "$report"
  tail -n 4 "$out/test.log" > "$out/test-summary.txt"
  fenced "$out/test-summary.txt"
fi

section "Light sweep: bench/courtyard.json at $sweep_size"
echo "Every technique at ${sweep_lights//,/, } lights, $frames frames after one warm-up frame;" \
     "a technique whose median frame passes $budget ms skips its larger counts." >> "$report"
"$ml" bench bench/courtyard.json --lights "$sweep_lights" --size "$sweep_size" --frames "$frames" \
  --budget-ms "$budget" --csv "$out/sweep.csv" --plot "$out/sweep.svg" "${device[@]}" > "$out/sweep.txt"
fenced "$out/sweep.txt"

section "Courtyard table (docs/performance.md) at $courtyard_size"
"$ml" bench bench/courtyard.json --lights "$courtyard_lights" --size "$courtyard_size" --frames "$frames" \
  --budget-ms "$budget" --csv "$out/courtyard.csv" "${device[@]}" > "$out/courtyard.txt"
fenced "$out/courtyard.txt"

if [ "${MASKED_LISTS:-1}" = 1 ]; then
  # The limit kMaskedListLights was chosen on llvmpipe (docs/techniques.md: the lists from bit
  # masks); on a GPU the masks' atomics against the sort are still to be measured.
  section "Light lists from bit masks against sorted pairs at $courtyard_size"
  echo "\`tiled\` and \`clustered\` at 1,024, 4,096 and 16,384 lights with their lists from bit masks" \
       "(the default), then sorted (MANYLIGHTS_MASKED_LIST_LIGHTS=0); \`--classic\`." >> "$report"
  for limit in default 0; do
    if [ "$limit" = default ]; then env=(); else env=(MANYLIGHTS_MASKED_LIST_LIGHTS=0); fi
    env "${env[@]}" "$ml" bench bench/courtyard.json --techniques clustered,tiled --lights 1024,4096,16384 \
      --size "$courtyard_size" --frames "$frames" --classic "${device[@]}" > "$out/lists-$limit.txt"
    echo "Lists: $([ "$limit" = default ] && echo 'from bit masks' || echo 'sorted')" >> "$report"
    fenced "$out/lists-$limit.txt"
  done
fi

if [ "${LEARNOPENGL:-1}" = 1 ]; then
  section "Against LearnOpenGL 8.1 (compare.sh, 800x600)"
  kit=../shared/peer/learnopengl-8.1
  if [ -x "$kit/compare.sh" ]; then
    # compare.sh picks its own context (the renderer's default device, hardware first).
    # shellcheck disable=SC2086
    if ML=$PWD/$ml OUT_DIR=$PWD/$out/learnopengl "$kit/compare.sh" $learnopengl_lights "$frames" \
         > "$out/learnopengl.out" 2> "$out/learnopengl.log"; then
      # Its table, without what the kit's own package install printed before it.
      sed -n '/^LearnOpenGL 8.1/,$p' "$out/learnopengl.out" > "$out/learnopengl.txt"
      fenced "$out/learnopengl.txt"
    else
      echo "compare.sh failed (log: $out/learnopengl.log)." >> "$report"
    fi
  else
    echo "Skipped: $kit/compare.sh is not there." >> "$report"
  fi
fi

echo "gpu-report: wrote $report" >&2
