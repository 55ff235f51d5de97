#!/usr/bin/env bash
# CI's time (docs/testing.md, "CI's time"): .ci/run on a fresh clone of COMMIT (default HEAD)
# as CI runs it, with nothing from ccache and an empty Mesa shader cache, so all three builds
# and every shader compile are cold. Prints the machine and its load, each step's time (.ci/run's
# "ci: STEP took N s" lines, make's own steps as their builds and CTest report them) and the
# load at the end; .ci/run's whole output is kept in OUTPUT (default out/ci-time.log). About 25
# minutes on 2 cores, and the machine should run nothing else meanwhile.
#
#   scripts/measure-ci-time.sh [COMMIT]
set -euo pipefail
cd "$(dirname "$0")/.."
commit=$(git rev-parse --verify "${1:-HEAD}^{commit}")
mkdir -p out
output=$(realpath "${OUTPUT:-out/ci-time.log}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q . "$work/clone"
git -C "$work/clone" checkout -q "$commit"
python3 -c 'import sys; sys.path.insert(0, "scripts/lib"); import bench; print(bench.machine_header([]).splitlines()[0])'
echo "commit: $commit"
status=0
(cd "$work/clone" && CCACHE_DISABLE=1 MESA_SHADER_CACHE_DIR="$work/mesa-shader-cache" .ci/run) >"$output" 2>&1 || status=$?
# make's steps: the builds' spans from their Ninja logs, the CTest runs' wall times.
for build in build build-sanitize build-fuzz; do
  log="$work/clone/$build/.ninja_log"
  [ -f "$log" ] && awk -v b="$build" 'NR > 1 { if (first == "" || $1 < first) first = $1; if ($2 > last) last = $2 }
    END { printf "build: %s built in %.0f s\n", b, (last - first) / 1000 }' "$log"
done
grep -E '^(ci: |Total Test time)' "$output"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "$status" -ne 0 ]; then
  echo "measure-ci-time: .ci/run failed (exit $status); see $output" >&2
  exit "$status"
fi
