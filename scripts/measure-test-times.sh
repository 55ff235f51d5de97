#!/usr/bin/env bash
# The suite's time (docs/testing.md, "The suite's time"): the sum of CTest's per-test times and
# the slowest tests, from the log of the last run (build/Testing/Temporary/LastTest.log); with
# two logs, both sums and the tests whose time changed most; with --interleave, the tests
# matching a regular expression run in two build folders in turn (ctest -j JOBS, 1 unless set;
# the order swapped every other round), each run's wall time and each test's times side by side;
# --interleave-gtest the same with two test programs and a GoogleTest filter; --processes, a
# filter's tests one process each (JOBS at a time) and all in one, with each program in turn.
# Prints the machine and its load first and last (scripts/lib/test_times.py).
#
#   (cd build && ctest -j 1) ; scripts/measure-test-times.sh
#   scripts/measure-test-times.sh before/LastTest.log build/Testing/Temporary/LastTest.log
#   ROUNDS=2 scripts/measure-test-times.sh --interleave 'SmallLights|Golden' /tmp/before/build build
#   JOBS=2 ROUNDS=2 scripts/measure-test-times.sh --interleave 'image\.(Techniques|EveryTechnique)/' /tmp/before/build build
#   ROUNDS=2 scripts/measure-test-times.sh --interleave-gtest '*OnOneSpot*' /tmp/before/image_tests build/tests/image_tests
#   ROUNDS=2 scripts/measure-test-times.sh --processes 'Techniques/Analytic.*' /tmp/before/image_tests build/tests/image_tests
#   TOP=40 scripts/measure-test-times.sh
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --interleave ]; then
  shift
  exec scripts/lib/test_times.py interleave "$@" --rounds "${ROUNDS:-2}" --jobs "${JOBS:-1}"
fi
if [ "${1:-}" = --processes ]; then
  shift
  exec scripts/lib/test_times.py processes "$@" --rounds "${ROUNDS:-2}" --jobs "${JOBS:-1}"
fi
if [ "${1:-}" = --interleave-gtest ]; then
  shift
  exec scripts/lib/test_times.py interleave-gtest "$@" --rounds "${ROUNDS:-2}"
fi
if [ $# = 2 ]; then
  exec scripts/lib/test_times.py compare "$1" "$2" --top "${TOP:-20}"
fi
exec scripts/lib/test_times.py sum "${1:-build/Testing/Temporary/LastTest.log}" --top "${TOP:-20}"
