#!/usr/bin/env bash
# Median frame time and per-pass fragment invocations of each technique on the default
# scene (the table in docs/techniques.md), through scripts/lib/bench.py: every pass with its
# median on the clock it was timed on, and forward's and deferred's passes' invocations.
# Usage: scripts/measure-techniques.sh [WxH] [frames]   (ML=, ROUNDS=, BENCH_ARGS=: docs/performance.md)
set -euo pipefail
cd "$(dirname "$0")/.."
exec scripts/lib/bench.py --frames "${2:-5}" --warmup 1 --passes \
  --column "depth pre-pass invocations=invocations.depth*" --column "geometry invocations=invocations.geometry" \
  --column "lighting invocations=invocations.lighting" \
  --case "default scene: --techniques forward,deferred --size ${1:-1280x720}"
