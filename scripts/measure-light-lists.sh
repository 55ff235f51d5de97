#!/usr/bin/env bash
# The many-lights figures of docs/performance.md and docs/techniques.md (issue 29): clustered
# and tiled on bench/courtyard.json from 1,024 to 1,048,576 lights at 1280x720, in one bench
# run (read the times as ratios within it), drawn to docs/images/many-lights-1280x720.svg;
# then the work at 640x360 (--count-work): the pairs in range, the light evaluations, the list
# entries walked, the (cluster, light) pairs, the rebuilds; and the GPU memory at 1280x720.
# The frames are timed without the display pass (--classic): the techniques' own work.
#
#   scripts/measure-light-lists.sh
#   OLD=/tmp/before/build/manylights scripts/measure-light-lists.sh
#        also that build's frames at 1,024, 4,096 and 16,384 lights (OLD_LIGHTS), interleaved
#        with this build's (e.g. git worktree add /tmp/before 029410a && make -C /tmp/before build)
#   OLD=... OLD_ONLY=1 OLD_LIGHTS=1024,16384,1048576 scripts/measure-light-lists.sh
#        that comparison alone (ROUNDS= rounds, default 2, the builds' order swapped every other
#        round; each line the frame and its clusters, pairs, sort or mask lists and lighting
#        passes, ms)
#   LIGHTS=1024,16384 SIZE=640x360 FRAMES=1 scripts/measure-light-lists.sh   a quicker look
set -euo pipefail
cd "$(dirname "$0")/.."
lights=${LIGHTS:-1024,4096,16384,65536,262144,1048576}
size=${SIZE:-1280x720}
frames=${FRAMES:-2}
mkdir -p out docs/images
source scripts/measure-common.sh
if [ -n "${OLD:-}" ]; then
  echo "== the build before against this one, interleaved (frame ms, median of $frames)"
  old_lights=${OLD_LIGHTS:-1024,4096,16384}
  # A build from before the display pass (029410a) has no --classic and no display pass to leave out.
  classic() { "$1" bench --help | grep -q -- --classic && echo --classic || true; }
  for round in $(seq "${ROUNDS:-2}"); do
    # Every other round the other build first, so that a load that changes meets both alike.
    binaries=("$OLD" "$ML")
    [ $((round % 2)) = 0 ] && binaries=("$ML" "$OLD")
    for binary in "${binaries[@]}"; do
      "$binary" bench bench/courtyard.json --techniques clustered,tiled --lights "$old_lights" --size "$size" \
        --frames "$frames" --warmup 1 $(classic "$binary") --csv out/measure-light-lists-ab.csv >/dev/null
      python3 - out/measure-light-lists-ab.csv "round $round $([ "$binary" = "$ML" ] && echo this || echo before)" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    passes = {p.split(":")[0]: float(p.split(":")[1]) for p in row["passes"].split(";")}
    print(f"{sys.argv[2]}: {row['technique']:<9} {int(row['lights']):>9,} lights: frame {float(row['frame_ms_median']):6.1f} ms;"
          + "".join(f" {name} {passes[name]:.0f}" for name in ("clusters", "cluster pairs", "pair sort", "mask lists", "lighting") if name in passes))
PY
    done
  done
  # Start-up with a million lights: a whole render of a tiny image (the lights' sort and upload,
  # render/scene/SceneLights.h, dominate it), the two builds interleaved.
  for round in 1 2; do
    for binary in "$OLD" "$ML"; do
      start=$(date +%s.%N)
      "$binary" render bench/courtyard.json --lights 1048576 --size 64x36 -o out/measure-light-lists-startup.pfm
      echo "round $round $([ "$binary" = "$ML" ] && echo this || echo before): render of 1,048,576 lights at 64x36:" \
        "$(python3 -c "print(round($(date +%s.%N) - $start, 2))") s"
    done
  done
  if [ -n "${OLD_ONLY:-}" ]; then
    echo "machine after: load average $(cut -d' ' -f1-3 /proc/loadavg)"
    exit 0
  fi
fi
echo "== $ML bench bench/courtyard.json --techniques clustered,tiled --lights $lights --size $size --classic"
"$ML" bench bench/courtyard.json --techniques clustered,tiled --lights "$lights" --size "$size" \
  --frames "$frames" --warmup 1 --classic --plot "docs/images/many-lights-${size}.svg" | tail -n +3
echo "== work at 640x360 (--count-work), and the GPU memory at $size"
python3 - "$ML" "$lights" "$size" <<'PY'
import json, subprocess, sys
ml, lights, size = sys.argv[1], sys.argv[2].split(","), sys.argv[3]
print("| lights | technique | in-range pairs | evaluations | / in range | list entries walked | / in range "
      "| cluster pairs | rebuilds | GPU memory at " + size + " |")
print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
def stats(technique, n, extra, size):
    out = "out/measure-light-lists.json"
    subprocess.run([ml, "render", "bench/courtyard.json", "-o", "out/measure-light-lists.pfm", "--lights", n,
                    "--size", size, "--technique", technique, "--stats", out] + extra, check=True)
    return json.load(open(out))
for n in lights:
    for technique in ("clustered", "tiled"):
        work = stats(technique, n, ["--count-work"], "640x360")
        memory = stats(technique, n, [], size)["gpu_memory_bytes"]
        in_range, evaluated, walked = work["in_range_pairs"], work["light_evaluations"], work["cluster_list_visits"]
        print(f"| {int(n):,} | {technique} | {in_range:,} | {evaluated:,} | {evaluated / in_range:.2f} "
              f"| {int(walked):,} | {walked / in_range:.1f} | {int(work['cluster_pairs']):,} "
              f"| {int(work['cluster_rebuilds'])} | {memory / 2**20:.0f} MiB |")
PY
echo "machine after: load average $(cut -d' ' -f1-3 /proc/loadavg)"
