#!/usr/bin/env bash
# The images of docs/display.md, made with the project's own commands (scripts/make-doc-images.sh
# runs this too): the same frames in the classic look (`--tonemap none --no-srgb`) and with the
# display path's options (PBR Neutral and sRGB being the default look), and crops that show the
# edges.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
ml=build/manylights
out=docs/images
plain=(--tonemap none --no-srgb)

# scenes/studio.json's gold, copper and red balls under AgX and PBR Neutral (why the default is
# the latter: scripts/measure-tone-curves.sh).
for curve in agx pbr-neutral; do
  $ml render scenes/studio.json -o $out/display-studio-$curve.png --size 640x360 --tonemap $curve --srgb --aa fxaa
done
# The default scene and the same scene with 4096 lights, each four ways.
for lights in default 4096; do
  count=()
  [ "$lights" = default ] || count=(--lights "$lights")
  $ml render "${count[@]}" -o $out/display-$lights-plain.png --size 640x360 "${plain[@]}"
  $ml render "${count[@]}" -o $out/display-$lights-aces.png --size 640x360 --tonemap aces --srgb --aa fxaa
  $ml render "${count[@]}" -o $out/display-$lights-agx.png --size 640x360 --tonemap agx --srgb --aa fxaa
  $ml render "${count[@]}" -o $out/display-$lights-pbr-neutral.png --size 640x360 --tonemap pbr-neutral --srgb \
    --aa fxaa
done
# With many lights a curve alone still leaves the floor near white: two stops down show it.
$ml render --lights 4096 -o $out/display-4096-aces-2ev.png --size 640x360 --tonemap aces --srgb --aa fxaa --exposure -2

# Edges: one 1280x720 frame's 160x90 crop, shown 4x enlarged without filtering: plain, FXAA,
# and --supersample 4 (16 samples per pixel, box-filtered in linear light).
crops=$(mktemp -d)
trap 'rm -rf "$crops"' EXIT
$ml render -o "$crops/none.png" --size 1280x720 --tonemap aces --srgb
$ml render -o "$crops/fxaa.png" --size 1280x720 --tonemap aces --srgb --aa fxaa
$ml render -o "$crops/supersample.png" --size 1280x720 --tonemap aces --srgb --supersample 4
for kind in none fxaa supersample; do
  convert "$crops/$kind.png" -crop 160x90+560+420 +repage -filter point -resize 400% $out/display-edges-$kind.png
done
echo "display images written to $out"
