#!/usr/bin/env bash
# The cost of the display path (docs/display.md): the default scene at 1280x720 with
# `clustered`, timed by bench in the classic look (`--classic`: no display pass runs), in the
# default look (PBR Neutral and sRGB), with FXAA as well, and under AgX (the default until
# issue 48); prints each pass's median wall time,
# its share of the frame, and both passes' share together. Prints the machine and its load
# first; read the figures as ratios within one run. REPEAT=N runs the four N times.
#
#   scripts/measure-display.sh                 SIZE=1920x1080 TECHNIQUE=deferred scripts/measure-display.sh
set -euo pipefail
cd "$(dirname "$0")/.."
size=${SIZE:-1280x720}
technique=${TECHNIQUE:-clustered}
mkdir -p out
source scripts/measure-common.sh
run() {
  local name=$1
  shift
  "$ML" bench --techniques "$technique" --size "$size" --frames "${FRAMES:-5}" --warmup 1 --csv "out/display-$name.csv" \
    "$@" >/dev/null
}
for ((i = 0; i < ${REPEAT:-1}; ++i)); do
run classic --classic
run default
run fxaa --aa fxaa
run agx --tonemap agx
python3 - "$technique" "$size" <<'PY'
import csv, sys
print(f"\n{sys.argv[1]}, default scene, {sys.argv[2]}: median ms (share of the frame)")
for name, label in (("classic", "--classic (no pass runs)"), ("default", "default: PBR Neutral, sRGB"),
                    ("fxaa", "default and --aa fxaa"), ("agx", "--tonemap agx (sRGB)")):
    row = next(csv.DictReader(open(f"out/display-{name}.csv")))
    frame = float(row["frame_ms_median"])
    passes = {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}
    ours = [p for p in ("display", "fxaa") if p in passes]
    shown = ", ".join(f"{p} {passes[p]:.1f} ({100 * passes[p] / frame:.1f} %)" for p in ours)
    if len(ours) > 1:
        both = sum(passes[p] for p in ours)
        shown += f", together {both:.1f} ({100 * both / frame:.1f} %)"
    print(f"  {label:26s} frame {frame:7.1f}  {shown}")
PY
done
