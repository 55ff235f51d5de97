#!/usr/bin/env bash
# How long the viewer goes without reading its input (docs/viewer.md "Controls", issue 48): it
# reads events at each frame's start, after each pass and every 10 ms of a wait for the GPU, so
# that a key's press and release are timed to within that gap, not to a frame. For each size
# and view, the viewer under Xvfb draws a few frames, then its panel report gives the last
# whole frame's length and the longest time it went without reading input. Prints the machine
# and its load first.
#
#   scripts/measure-input-gaps.sh
#   SIZES="320x180 1920x1080" scripts/measure-input-gaps.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/measure-common.sh
sizes=${SIZES:-320x180 1280x720 1920x1080}
views=${VIEWS:-final light-count}
out=out/input-gaps
mkdir -p "$out"
ml=$(realpath "$ML")
printf '%-10s %-12s %10s %22s\n' size view frame_ms longest_input_gap_ms
for size in $sizes; do
  for view in $views; do
    width=${size%x*}
    height=${size#*x}
    printf 'view %s\nresize %s %s\nframes 4\nreport-panel report.txt\nquit\n' "$view" "$width" "$height" \
      >"$out/script.txt"
    rm -f "$out/report.txt"
    (cd "$out" && xvfb-run -a -s '-screen 0 2000x1200x24' "$ml" view --script script.txt \
      --size "$size" >view.log 2>&1)
    read -r _ frame_ms gap_ms < <(grep '^input ' "$out/report.txt")
    printf '%-10s %-12s %10s %22s\n' "$size" "$view" "$frame_ms" "$gap_ms"
  done
done
