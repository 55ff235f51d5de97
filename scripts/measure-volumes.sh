#!/usr/bin/env bash
# Median frame time, lighting-pass time (on the clock it was timed on) and fragment invocations,
# and light evaluations against in-range pairs (--count-work: one untimed frame more), of
# deferred, volumes and stencil on the default scene at 1280x720 with 256, 1024 and 4096 lights
# (the table in docs/techniques.md), through scripts/lib/bench.py.
# Usage: scripts/measure-volumes.sh [frames]   (ML=, ROUNDS=, BENCH_ARGS=: docs/performance.md)
set -euo pipefail
cd "$(dirname "$0")/.."
exec scripts/lib/bench.py --frames "${1:-3}" --warmup 1 --column lighting \
  --column "invocations=invocations.lighting" --column "evaluations=work.light_evaluations" \
  --column "in range=work.in_range_pairs" \
  --case "default scene: --techniques deferred,volumes,stencil --lights 256,1024,4096 --count-work"
