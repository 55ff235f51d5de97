#!/usr/bin/env bash
# Regenerates every image in docs/images/ with the project's own commands. The figures in
# docs/techniques.md come from scripts/measure-techniques.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
make build
ml=build/manylights
out=docs/images

# README picture: the default scene as `make run` renders it.
$ml render -o $out/default-scene.png --size 1280x720

# Every G-buffer quantity of the default scene (docs/gbuffer.md).
for view in position normal diffuse specular emissive depth; do
  $ml render -o $out/gbuffer-$view.png --size 640x360 --view $view
done

# Textures and normal maps (docs/scene-format.md): the textured test scene, lit and its normals.
$ml render tests/scenes/textured_normal_mapped.json -o $out/textured-normal-mapped.png --size 640x384
$ml render tests/scenes/textured_normal_mapped.json -o $out/textured-normal-mapped-normals.png --size 640x384 \
  --view normal

# The example scenes with real assets (scenes/, docs/scene-format.md "Model files").
$ml render scenes/bunny-teapot.json -o $out/scene-bunny-teapot.png --size 640x360
$ml render scenes/gltf-models.json -o $out/scene-gltf-models.png --size 640x360
$ml render scenes/textured-normal-mapped.json -o $out/scene-textured-normal-mapped.png --size 640x384 \
  --shadow-lights 2

# Transparency (docs/transparency.md): the glass scene, and the light-count view of its
# transparent surfaces' grid against forward's every light.
$ml render scenes/glass.json -o $out/scene-glass.png --size 960x540 --technique clustered
$ml render scenes/glass.json -o $out/glass-light-count-clustered.png --size 640x360 --technique clustered \
  --view light-count

# The metallic-roughness model beside the old Blinn-Phong mapping (docs/lighting.md).
scripts/make-pbr-images.sh

# The techniques side by side (docs/techniques.md).
for technique in forward deferred volumes stencil tiled-quads tiled clustered; do
  $ml render -o $out/technique-$technique.png --size 640x360 --technique $technique
done
for technique in deferred volumes stencil tiled-quads tiled clustered; do
  $ml render -o $out/light-count-$technique.png --size 640x360 --technique $technique --view light-count
done
# A few lights, so that the scene shows between the wireframes.
$ml render -o $out/volumes-view.png --size 640x360 --technique stencil --view volumes --lights 24
# The animation (README): a strip of four moments and a looping GIF, recorded with
# --time-range and put together with ImageMagick.
frames=$(mktemp -d)
trap 'rm -rf "$frames"' EXIT
$ml render --time-range 0:3 --fps 10 --size 320x180 -o "$frames/%03d.png"
convert -delay 10 -loop 0 "$frames"/*.png -colors 128 -layers Optimize $out/animation.gif
$ml render --time-range 0:3 --fps 1 --size 480x270 -o "$frames/strip-%d.png"
montage "$frames"/strip-0.png "$frames"/strip-1.png "$frames"/strip-2.png -tile 3x1 -geometry +4+0 \
  -background black $out/animation-strip.png
# The benchmark scene of docs/performance.md at its reference light count.
$ml render bench/courtyard.json -o $out/courtyard.png --size 640x360 --lights 1024
# Shadows and SSAO (docs/shadows.md): one scene without and with them, and the two views.
variants=$(mktemp -d)
trap 'rm -rf "$variants"' EXIT
scripts/shadow-scene-variants.py docs/scenes/shadows.json "$variants"
$ml render "$variants/plain.json" -o $out/shadows-none.png --size 640x360
$ml render "$variants/shadows.json" -o $out/shadows-directional.png --size 640x360
$ml render "$variants/shadows.json" -o $out/shadows-all.png --size 640x360 --shadow-lights 3
$ml render "$variants/both.json" -o $out/shadows-and-ssao.png --size 640x360 --shadow-lights 3
$ml render "$variants/shadows.json" -o $out/view-shadow.png --size 640x360 --view shadow
$ml render "$variants/both.json" -o $out/view-ssao.png --size 640x360 --view ssao
# Every light shadowed through the shadow-page pool (docs/shadows.md), beside courtyard.png.
$ml render bench/courtyard.json -o $out/courtyard-every-light-shadowed.png --size 640x360 --lights 1024 \
  --shadow-lights all
# The shadow-resolution view (docs/shadows.md) of the default scene with every light shadowed:
# in the default pool, and in the smallest, which lowers the faces' levels.
$ml render -o $out/view-shadow-resolution.png --size 640x360 --view shadow-resolution --shadow-lights all
$ml render -o $out/view-shadow-resolution-small-pool.png --size 640x360 --view shadow-resolution \
  --shadow-lights all --shadow-pool-mib 4
# The display path (docs/display.md).
scripts/make-display-images.sh
echo "docs images written to $out"
