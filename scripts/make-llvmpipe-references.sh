#!/usr/bin/env bash
# forward's images on llvmpipe, for scripts/gpu-report.sh to compare a GPU's forward with
# (docs/testing.md: "forward on a GPU against forward on llvmpipe"): each scene at 320x180 as a
# PFM, with --anisotropy 1 (the GPU's default of 8x differs by design) and with the software
# profile's other choices. Run here, then carry the folder to the GPU machine and give it to the
# report as REFERENCE_DIR.
#
#   scripts/make-llvmpipe-references.sh [DIR]     (default out/llvmpipe-references)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-out/llvmpipe-references}
ml=${ML:-build/manylights}
mkdir -p "$dir"
# name and scene ("" is the built-in default scene); the list gpu-report.sh walks.
while read -r name scene; do
  "$ml" render $scene -o "$dir/$name.pfm" --size 320x180 --technique forward --anisotropy 1 \
    --driver-profile software
  echo "$name $scene" >> "$dir/scenes.txt.part"
done <<'LIST'
default
textured scenes/textured-normal-mapped.json
pbr scenes/pbr-models.json
gltf scenes/gltf-models.json
bunny scenes/bunny-teapot.json
glass scenes/glass.json
LIST
mv "$dir/scenes.txt.part" "$dir/scenes.txt"
"$ml" render -o "$dir/probe.png" --size 16x16 --stats "$dir/device.json" > /dev/null
python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["device"])' "$dir/device.json" > "$dir/device.txt"
rm -f "$dir/probe.png" "$dir/device.json"
echo "wrote $(wc -l < "$dir/scenes.txt") references to $dir ($(cat "$dir/device.txt"))"
