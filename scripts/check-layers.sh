#!/usr/bin/env bash
# Checks the layer table of CODE_STYLE.md ("Layers"): a file of a layer includes project
# headers only from its own folder and the layers that table lists after it. Prints each
# include that crosses the table as FILE:LINE: LAYER includes WHAT, and exits 1 if there is
# one. Headers of shaders/ (shared with the GLSL, such as shaders/lib/bindings.glsl) may be
# included from any layer. Tests, benchmarks and fuzz targets are not checked. Changes nothing.
#
#   scripts/check-layers.sh
set -euo pipefail
cd "$(dirname "$0")/.."

# The layer of a path (its first folder: platform/window/ is the platform layer, render/frame/
# the render layer) and the layers it may include from, as in CODE_STYLE.md.
allowed_for() {
  case "$1" in
    apps) echo "apps render scene gl platform core" ;;
    render) echo "render scene gl core" ;;
    scene) echo "scene core" ;;
    platform) echo "platform gl core" ;;
    gl) echo "gl core" ;;
    core) echo "core" ;;
  esac
}

status=0
while IFS= read -r file; do
  layer="${file%%/*}"
  allowed="$(allowed_for "$layer") shaders"
  while IFS=: read -r line target; do
    included="${target%%/*}"
    # An include without a folder is a file next to this one or a library's; a .glsl file is
    # a shader (found on shaders/, the include path scene/Falloff.cpp uses).
    [[ "$target" == */* && "$target" != *.glsl ]] || continue
    if [[ " $allowed " != *" $included "* ]]; then
      echo "$file:$line: $layer includes $target"
      status=1
    fi
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" | sed 's/:[^"]*"\([^"]*\)".*/:\1/')
done < <(git ls-files 'core/*' 'gl/*' 'platform/*' 'scene/*' 'render/*' 'apps/*' | grep -E '\.(h|cpp)$')
if [[ $status -ne 0 ]]; then
  echo "check-layers: the includes above cross the layer table of CODE_STYLE.md" >&2
fi
exit $status
