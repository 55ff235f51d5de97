#!/usr/bin/env bash
# A cold build's time file by file and in unity batches (docs/testing.md, "CI's time"): clones
# COMMIT (default HEAD) once, then builds everything from nothing, without ccache, both ways in
# turn, ROUNDS times (default 1; the order swapped every other round), and prints each build's
# wall time and its compilers' CPU seconds (user and system, all processes together). BUILD says
# which configuration: release (make test's, the default) or sanitize (make sanitize's Debug
# build under ASan and UBSan). The machine should run nothing else meanwhile.
#
#   scripts/measure-build-time.sh [COMMIT]
#   BUILD=sanitize ROUNDS=2 scripts/measure-build-time.sh
set -euo pipefail
cd "$(dirname "$0")/.."
commit=$(git rev-parse --verify "${1:-HEAD}^{commit}")
rounds=${ROUNDS:-1}
jobs=${JOBS:-$(nproc)}
case "${BUILD:-release}" in
release) flags=(-DCMAKE_BUILD_TYPE=Release -DMANYLIGHTS_WERROR=ON) ;;
sanitize) flags=(-DCMAKE_BUILD_TYPE=Debug -DMANYLIGHTS_WERROR=ON -DMANYLIGHTS_SANITIZE=ON) ;;
*)
  echo "measure-build-time: BUILD must be release or sanitize, not '$BUILD'" >&2
  exit 1
  ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q . "$work/clone"
git -C "$work/clone" checkout -q "$commit"
python3 -c 'import sys; sys.path.insert(0, "scripts/lib"); import bench; print(bench.machine_header([]))' |
  sed "s/^commit: .*/commit: $commit/"
echo "build: ${BUILD:-release}, $jobs jobs"

# One cold build with unity batches ON or OFF: "unity=ON: 174 s wall, 324 CPU-s".
build() {
  local unity=$1 dir="$work/build-$1"
  rm -rf "$dir"
  cmake -S "$work/clone" -B "$dir" -G Ninja "${flags[@]}" -DCMAKE_UNITY_BUILD="$unity" >/dev/null
  local TIMEFORMAT='%R %U %S' times
  times=$({ time CCACHE_DISABLE=1 cmake --build "$dir" -j "$jobs" >"$work/build.log" 2>&1; } 2>&1) || {
    tail -20 "$work/build.log" >&2
    exit 1
  }
  read -r wall user system <<<"$times"
  awk -v u="$unity" -v w="$wall" -v us="$user" -v sy="$system" \
    'BEGIN { printf "unity=%s: %.0f s wall, %.0f CPU-s\n", u, w, us + sy }'
}

for ((round = 1; round <= rounds; round++)); do
  echo "round $round"
  if ((round % 2)); then order=(OFF ON); else order=(ON OFF); fi
  for unity in "${order[@]}"; do build "$unity"; done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
