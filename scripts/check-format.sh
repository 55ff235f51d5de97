#!/usr/bin/env bash
# Checks that every tracked C++ file (git ls-files '*.cpp' '*.h') is formatted as .clang-format
# says: runs `clang-format --dry-run --Werror` on each, prints the name of every file it would
# change and exits 1 if there is one (2 if clang-format is missing or fails). Changes nothing.
# GLSL (shaders/) is not checked.
#
#   scripts/check-format.sh           the check (CLANG_FORMAT=path picks another binary)
#   clang-format -i FILE...           reformats files in place, to fix what it reports
#
# .clang-format is written for clang-format 14 (Debian 12's); other versions break some
# lines differently, so a different version is named in a warning.
set -euo pipefail
cd "$(dirname "$0")/.."

clang_format="${CLANG_FORMAT:-clang-format}"
if ! command -v "$clang_format" >/dev/null 2>&1; then
  echo "check-format: $clang_format not found (Debian: apt-get install clang-format)" >&2
  exit 2
fi
version="$("$clang_format" --version)"
if [[ ! "$version" =~ version\ 14\. ]]; then
  echo "check-format: warning: .clang-format is written for clang-format 14, this is: $version" >&2
fi

mapfile -d '' files < <(git ls-files -z -- '*.cpp' '*.h')
unformatted=()
for file in "${files[@]}"; do
  [[ -f "$file" ]] || continue  # tracked but deleted in the working tree
  if ! output="$("$clang_format" --style=file --dry-run --Werror "$file" 2>&1)"; then
    if [[ "$output" != *"-Wclang-format-violations"* ]]; then
      # Not a formatting difference (an unreadable .clang-format, a crash): say what.
      echo "check-format: clang-format failed on $file:" >&2
      echo "$output" >&2
      exit 2
    fi
    unformatted+=("$file")
  fi
done

if ((${#unformatted[@]} > 0)); then
  echo "check-format: ${#unformatted[@]} of ${#files[@]} C++ files are not formatted as .clang-format says:" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  echo "check-format: see the changes with: clang-format FILE | diff FILE -" >&2
  exit 1
fi
echo "check-format: all ${#files[@]} C++ files are formatted"
