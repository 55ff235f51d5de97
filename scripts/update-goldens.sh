#!/usr/bin/env bash
# Re-renders the golden images of tests/golden/ with the current build. Look at every
# changed image (git diff --stat tests/golden; open them) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
make build
cd build && MANYLIGHTS_UPDATE_GOLDENS=1 ./tests/image_tests --gtest_filter='Images/Golden.*'
