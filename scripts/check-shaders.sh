#!/usr/bin/env bash
# Checks the shader programs the renderer builds with Khronos's reference compiler,
# glslangValidator (Debian's glslang-tools), as GLSL 4.50 core (issue 30). Mesa accepts GLSL
# that NVIDIA's and AMD's compilers may refuse; glslang keeps to the specification, so what it
# accepts a vendor compiler should too.
#
# The renderer writes every stage it compiles, after the include and #define expansion, to the
# folder MANYLIGHTS_SHADER_DUMP names (gl/Program.cpp), once per distinct text. So:
#
#   scripts/check-shaders.sh DIR   checks the stages already dumped in DIR; CI (.ci/run) runs
#                                  `make test` with MANYLIGHTS_SHADER_DUMP=DIR first, so every
#                                  variant the tests build, under both driver profiles, is checked
#   scripts/check-shaders.sh       renders small frames that build every technique in both
#                                  G-buffer layouts and both driver profiles, every view, the
#                                  display pass, shadows, SSAO, transparency and an environment,
#                                  then checks those
#
# Exits 1 naming each stage glslang rejects (its messages follow), 0 when all pass.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v glslangValidator >/dev/null; then
  echo "check-shaders: glslangValidator is missing (scripts/setup.sh installs glslang-tools)" >&2
  exit 1
fi

dump=${1:-}
if [ -z "$dump" ]; then
  exe=${MANYLIGHTS:-build/manylights}
  [ -x "$exe" ] || { echo "check-shaders: $exe is not built (make build)" >&2; exit 1; }
  dump=build/shader-dump
  rm -rf "$dump"
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
  export MANYLIGHTS_SHADER_DUMP=$PWD/$dump
  techniques=(forward deferred volumes stencil tiled-quads tiled clustered)
  views=$("$exe" render --help | sed -n 's/.*--view TEXT:{\([^}]*\)}.*/\1/p' | tr ',' ' ')
  render() { "$exe" render "$@" -o "$out/frame.pfm" --size 48x32 >/dev/null; }
  for profile in software gpu; do
    for technique in "${techniques[@]}"; do
      for layout in seed compact; do
        render --driver-profile "$profile" --technique "$technique" --gbuffer "$layout" --count-work \
          --stats "$out/stats.json"
        render tests/scenes/textured_normal_mapped.json --driver-profile "$profile" --technique "$technique" \
          --gbuffer "$layout"
      done
      render tests/scenes/shadows_and_ssao.json --driver-profile "$profile" --technique "$technique" \
        --shadow-lights 4
      render tests/scenes/spots_and_points.json --driver-profile "$profile" --technique "$technique"
      render scenes/glass.json --driver-profile "$profile" --technique "$technique"
      render scenes/gltf-models.json --driver-profile "$profile" --technique "$technique"
      # An environment: its prefiltering, its background and the lighting's image-based light.
      render scenes/studio.json --driver-profile "$profile" --technique "$technique"
    done
    for view in $views; do
      render tests/scenes/shadows_and_ssao.json --driver-profile "$profile" --view "$view" --shadow-lights 4
    done
    "$exe" render --driver-profile "$profile" -o "$out/frame.png" --size 48x32 --aa fxaa --supersample 2 \
      --exposure 0.5 >/dev/null
  done
fi

shopt -s nullglob
stages=("$dump"/*.vert "$dump"/*.frag "$dump"/*.comp)
if [ ${#stages[@]} -eq 0 ]; then
  echo "check-shaders: no shader stages in $dump" >&2
  exit 1
fi
# glslangValidator compiles each file it is given as its own stage, and most of a run's time
# is its start (it builds the built-in symbol tables for each stage kind once per process), so
# the stages go in batches: on the 2-core machine (2026-11-29, a build running beside it) the
# 1,668 stages of a CI run took 128 s one process each and 7 s in batches. Only a batch that
# fails is run again a stage at a time, to name each rejected stage with its own messages.
batch_size=200
failed=0
for ((first = 0; first < ${#stages[@]}; first += batch_size)); do
  batch=("${stages[@]:first:batch_size}")
  if glslangValidator "${batch[@]}" >/dev/null 2>&1; then
    continue
  fi
  for stage in "${batch[@]}"; do
    if ! log=$(glslangValidator "$stage" 2>&1); then
      echo "check-shaders: glslang rejects $stage:" >&2
      echo "$log" | grep -v "^$stage\$" | head -20 >&2
      failed=$((failed + 1))
    fi
  done
done
echo "check-shaders: ${#stages[@]} stages checked with $(glslangValidator --version | head -1), $failed rejected"
[ "$failed" -eq 0 ]
