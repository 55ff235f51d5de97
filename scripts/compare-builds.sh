#!/usr/bin/env bash
# Renders one set of images with two builds and compares them byte for byte: the check that a
# change of structure changes no image (issue 46: "every image, count and exit code stays the
# same"). The set covers every technique on the default scene under both driver profiles and
# both lighting stages, the courtyard at 4,096 lights, the scenes the docs show (model files,
# textures and normal maps, transparency, local shadows, the metallic-roughness models), the
# G-buffer and light-count views and a larger size; linear images (.pfm), so that the display
# curve, which a change may mean to alter, is left out. Prints one line per image (same or
# DIFFERENT, with the first differing byte) and a summary; exits 1 if any image differs or
# either build fails to render it.
#
#   scripts/compare-builds.sh OLD_BINARY NEW_BINARY [OUT_DIR]
#
# For example, against the build of an older commit in a second worktree:
#   git worktree add ../base ece069e && (cd ../base && CMAKE_FLAGS=-DMANYLIGHTS_TESTS=OFF make build)
#   scripts/compare-builds.sh ../base/build/manylights build/manylights
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then
  echo "usage: $0 OLD_BINARY NEW_BINARY [OUT_DIR]" >&2
  exit 2
fi
old=$1
new=$2
out=${3:-out/compare-builds}
rm -rf "$out"
mkdir -p "$out/old" "$out/new"
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "old: $old"
echo "new: $new"

# One case a line: a name, then the render arguments (the output is added).
cases=()
for profile in software gpu; do
  for technique in forward deferred volumes stencil tiled-quads tiled clustered; do
    cases+=("default-$technique-$profile|--size 320x180 --technique $technique --driver-profile $profile")
  done
  for stage in fragment compute; do
    for technique in deferred clustered; do
      cases+=("lights4096-$technique-$stage-$profile|bench/courtyard.json --lights 4096 --size 320x180 --technique $technique --lighting-stage $stage --driver-profile $profile")
    done
  done
done
for technique in forward tiled clustered stencil; do
  cases+=("courtyard-4096-$technique|bench/courtyard.json --lights 4096 --size 640x360 --technique $technique")
done
cases+=("default-1280x720|--size 1280x720")
cases+=("bunny-teapot|scenes/bunny-teapot.json --size 320x180")
cases+=("gltf-models|scenes/gltf-models.json --size 320x180")
cases+=("textured-shadows|scenes/textured-normal-mapped.json --size 320x192 --shadow-lights 2")
cases+=("glass-clustered|scenes/glass.json --size 320x180 --technique clustered")
cases+=("glass-forward|scenes/glass.json --size 320x180 --technique forward")
cases+=("shadows-ssao|tests/scenes/shadows_and_ssao.json --size 320x180 --technique deferred")
cases+=("lights-on-one-spot|tests/scenes/lights_on_one_spot.json --size 320x180 --technique clustered")
for view in normal depth light-count; do
  cases+=("view-$view|--size 320x180 --view $view")
done

status=0
differing=0
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a args <<<"${entry#*|}"
  for side in old new; do
    binary=$old
    [ "$side" = new ] && binary=$new
    if ! "$binary" render "${args[@]}" -o "$out/$side/$name.pfm" >"$out/$side/$name.log" 2>&1; then
      echo "$name: the $side build failed: $(tail -1 "$out/$side/$name.log")"
      status=1
      continue 2
    fi
  done
  if difference=$(cmp "$out/old/$name.pfm" "$out/new/$name.pfm" 2>&1); then
    echo "$name: same"
  else
    echo "$name: DIFFERENT ($difference)"
    differing=$((differing + 1))
    status=1
  fi
done
echo "${#cases[@]} images, $differing different"
exit $status
