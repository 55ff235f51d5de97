#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) in build-fuzz/ and
# runs each for SECONDS (default 20), JOBS (default 2) at a time, on a seed corpus made from the
# repository's scenes and models (and Debian's assimp-testmodels glTFs when installed). Exits
# non-zero when any target crashed; libFuzzer leaves the input under build-fuzz/artifacts/.
# Turn it into a regression test (tests/unit) before fixing it.
#
#   scripts/fuzz.sh [SECONDS]     e.g. scripts/fuzz.sh 120 for a longer run by hand
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
jobs="${JOBS:-2}"
build=build-fuzz

./scripts/setup.sh
if [ ! -f "$build/build.ninja" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DMANYLIGHTS_FUZZ=ON -DMANYLIGHTS_TESTS=OFF -DMANYLIGHTS_WERROR=ON
fi
cmake --build "$build" -j "$jobs" --target FuzzSceneJson FuzzObj FuzzGltf FuzzCommandLine

# Seeds: copied fresh each run (read-only for libFuzzer); what it finds goes into
# $build/corpus/<target>, kept between runs.
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds/FuzzSceneJson" "$seeds/FuzzObj" "$seeds/FuzzGltf" "$seeds/FuzzCommandLine" "$build/artifacts"
cp tests/scenes/*.json tests/data/scene/example.json scenes/*.json "$seeds/FuzzSceneJson/"
cp assets/models/bunny-lowres.obj assets/models/teapot-lowres.obj tests/data/scene/models/*.obj \
  tests/data/models/*.obj "$seeds/FuzzObj/"
# An OBJ with its material library, in the target's "OBJ, #MTL, MTL" form.
{ cat tests/data/models/two-materials.obj; printf '\n#MTL\n'; cat tests/data/models/two-materials.mtl; } \
  > "$seeds/FuzzObj/two-materials-with-mtl"
cp assets/models/*.gltf "$seeds/FuzzGltf/"
assimp=/usr/share/assimp/models/glTF2
if [ -d "$assimp" ]; then
  for f in BoxTextured-glTF-Binary/BoxTextured.glb BoxTextured-glTF-Embedded/BoxTextured.gltf \
           BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb IndexOutOfRange/IndexOutOfRange.gltf \
           RecursiveNodes/RecursiveNodes.gltf IncorrectVertexArrays/Cube.gltf \
           BoxBadNormals-glTF-Binary/BoxBadNormals.glb; do
    cp "$assimp/$f" "$seeds/FuzzGltf/$(echo "$f" | tr / _)"
  done
fi

# Command-line seeds: a first byte choosing the parser (see FuzzCommandLine.cpp), then text.
printf '\0%s' 2.5 > "$seeds/FuzzCommandLine/number"
printf '\1%s' 1280x720 > "$seeds/FuzzCommandLine/size"
printf '\2%s' '0:4 30' > "$seeds/FuzzCommandLine/time-range"
printf '\3%s' 'frames/%04d.png' > "$seeds/FuzzCommandLine/pattern"
printf '\4%s' all > "$seeds/FuzzCommandLine/shadow-lights"
printf '\5%s' 256 > "$seeds/FuzzCommandLine/shadow-pool"
printf '\6%s' "$(printf 'frames 2\nresize 640 360\ntime 1.5\nspeed 2\nscreenshot a.png\nquit')" \
  > "$seeds/FuzzCommandLine/script"

# One target's run; its report goes to its log, then to the output in one piece.
fuzz_target() {
  local target=$1 corpus="$build/corpus/$1" log="$build/artifacts/$1.log" status=0
  mkdir -p "$corpus"
  # -rss_limit_mb: an input may ask for a large (but bounded) allocation; more is a bug.
  "$build/tests/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb="${FUZZ_RSS_MB:-2048}" -max_len=65536 \
    -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 "$corpus" "$seeds/$target" \
    >"$log" 2>&1 || status=$?
  echo "fuzz: $target for ${seconds}s"
  grep -E '^(stat::number_of_executed_units|==[0-9]+==|SUMMARY)|ERROR|Test unit written' "$log" || true
  if [ "$status" -ne 0 ]; then
    echo "fuzz: $target failed (exit $status); see $log and $build/artifacts/" >&2
    return 1
  fi
}

# A libFuzzer run uses one core: the targets run JOBS at a time (on 2 cores the four take twice
# SECONDS, not four times). Every target runs its time; any that failed fails the script.
pids=()
failed=0
for target in FuzzSceneJson FuzzObj FuzzGltf FuzzCommandLine; do
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
  fuzz_target "$target" &
  pids+=($!)
done
for pid in "${pids[@]}"; do
  wait "$pid" || failed=1
done
[ "$failed" -eq 0 ] || exit 1
echo "fuzz: no crash in ${seconds}s per target"
