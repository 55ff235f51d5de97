#!/usr/bin/env bash
# Checks the layer table of CODE_STYLE.md ("Layers"): a file of a layer includes project
# headers only from its own folder and the layers that table lists after it; and inside
# render/, the order of its rooms (the second table): a file of a room includes only from its
# own room and the rooms below it, and render/'s own files (the Renderer, the registry of
# techniques) from any room. Prints each include that crosses a table as FILE:LINE: LAYER
# includes WHAT, and exits 1 if there is one. Headers of shaders/ (shared with the GLSL, such as shaders/lib/bindings.glsl) may be
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

# render/'s rooms from the bottom up, as CODE_STYLE.md tables them: a room may include from the
# rooms before it in this list.
render_rooms=(driver programs output environment scene frame culling effects techniques shadows volumes)

room_rank() {
  local i
  for i in "${!render_rooms[@]}"; do
    [[ "${render_rooms[$i]}" == "$1" ]] && { echo "$i"; return; }
  done
  echo ""
}

status=0
# Every room of render/ is in the order: a new folder must be placed in it.
while IFS= read -r room; do
  if [[ -z "$(room_rank "$room")" ]]; then
    echo "render/$room/: not in the order of render's rooms (scripts/check-layers.sh, CODE_STYLE.md)"
    status=1
  fi
done < <(git ls-files 'render/*/*' | cut -d/ -f2 | sort -u)

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
    # Inside render/: a room includes from its own room and those below it only.
    if [[ "$layer" == render && "$included" == render && "$file" == render/*/* ]]; then
      from="$(room_rank "$(cut -d/ -f2 <<<"$file")")"
      rest="${target#render/}"
      if [[ "$rest" != */* ]]; then
        echo "$file:$line: a room of render includes render's own $target"
        status=1
      elif [[ -n "$from" ]]; then
        to="$(room_rank "${rest%%/*}")"
        if [[ -n "$to" && "$to" -gt "$from" ]]; then
          echo "$file:$line: render/${render_rooms[$from]} includes $target, a room above it"
          status=1
        fi
      fi
    fi
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" | sed 's/:[^"]*"\([^"]*\)".*/:\1/')
done < <(git ls-files 'core/*' 'gl/*' 'platform/*' 'scene/*' 'render/*' 'apps/*' | grep -E '\.(h|cpp)$')
if [[ $status -ne 0 ]]; then
  echo "check-layers: the includes above cross the layer table of CODE_STYLE.md" >&2
fi
exit $status
