#!/usr/bin/env bash
# Checks of scripts/gpu-report.sh that need no GPU (issue 40), on llvmpipe, in about half a minute:
#   1. without ML, a `make` that fails: one clear line on stderr, exit 1;
#   2. with ML, a `make`, `apt-get`, `apt` and `sudo` on PATH that leave a marker: none is called,
#      and every section is in the report; stand-in test programs (gtest's output format) check
#      the tests' summary: a failure with its lines, a skip with its reason, image.gpu. run with
#      tests/CMakeLists.txt's filter and environment, a shard cut at its time box;
#   3. a time box that expires (the sweep's): the report says so and the later sections run;
#      the whole budget (TOTAL_S) spent: the sections left say so;
#   4. the report stopped from outside mid-run: the sections that finished are in it.
# Not part of `make test` (it renders for half a minute): run it after changing gpu-report.sh.
# Usage: scripts/test-gpu-report.sh   (after make build; ML=FILE for another executable;
#        LOGL_PREBUILT=DIR to run the LearnOpenGL section for real instead of its "skipped" path)
set -euo pipefail
cd "$(dirname "$0")/.."
ml=${ML:-build/manylights}
[ -x "$ml" ] || { echo "test-gpu-report: no $ml: run make build first (or set ML=)" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/test-gpu-report.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
passes=0 failures=0
check() {   # check DESCRIPTION COMMAND...: one line, ok or FAILED
  if "${@:2}"; then echo "ok      $1"; passes=$((passes + 1)); else echo "FAILED  $1"; failures=$((failures + 1)); fi
}
has() { grep -qF -- "$2" "$1"; }           # has FILE TEXT
section() {                                 # section FILE TITLE-START: that section's text
  awk -v t="## $2" 'index($0, t) == 1 { on = 1; print; next } /^## / { on = 0 } on' "$1"
}

# --- 1. make fails, no ML ---
mkdir -p "$tmp/failing"
printf '#!/bin/sh\nexit 1\n' > "$tmp/failing/make"
chmod +x "$tmp/failing/make"
rc=0
env -u ML PATH="$tmp/failing:$PATH" scripts/gpu-report.sh --anyway --out "$tmp/1" > "$tmp/1.out" 2> "$tmp/1.err" || rc=$?
check "without ML, a failing make build: exit 1" [ "$rc" = 1 ]
check "... and one line on stderr saying so" [ "$(wc -l < "$tmp/1.err")" = 1 ]
check "... which names make build and ML" grep -q 'make build failed.*ML=' "$tmp/1.err"
cat "$tmp/1.err"

# --- 2. and 3. ML given: nothing built or installed; every section; the sweep's box expires ---
mkdir -p "$tmp/marking" "$tmp/bin" "$tmp/empty"
for tool in make apt-get apt sudo; do
  printf '#!/bin/sh\necho "%s $*" >> %s/called\nexit 1\n' "$tool" "$tmp" > "$tmp/marking/$tool"
  chmod +x "$tmp/marking/$tool"
done
# Stand-ins for the test programs, printing as gtest does. gl_tests: shard 0 has a failure and a
# skip. image_tests: under the GPU profile it records its arguments; else it hangs in a test, so
# that its shards are cut at the time box.
cat > "$tmp/bin/gl_tests" <<'EOF'
#!/bin/sh
i=$GTEST_SHARD_INDEX
[ "$i" = 0 ] && echo "[==========] Running 3 tests from 1 test suite." || echo "[==========] Running 1 test from 1 test suite."
echo "[ RUN      ] Fake.Passes$i"; echo "[       OK ] Fake.Passes$i (1 ms)"
[ "$i" = 0 ] || exit 0
echo "[ RUN      ] Fake.Fails"; echo "fake.cpp:12: Failure"; echo "Expected equality of these values: 1 and 2"
echo "[  FAILED  ] Fake.Fails (3 ms)"
echo "[ RUN      ] Fake.Skips"; echo "fake.cpp:20: Skipped"; echo "no GPU here"; echo "[  SKIPPED ] Fake.Skips (0 ms)"
echo "[  FAILED  ] 1 test, listed below:"; echo "[  FAILED  ] Fake.Fails"
exit 1
EOF
cat > "$tmp/bin/image_tests" <<EOF
#!/bin/sh
if [ "\${MANYLIGHTS_TEST_DRIVER_PROFILE:-}" = gpu ]; then
  echo "\$*" >> "$tmp/gpu-args"
  echo "[==========] Running 1 test from 1 test suite."
  echo "[ RUN      ] Gpu.Passes"; echo "[       OK ] Gpu.Passes (1 ms)"; exit 0
fi
echo "[==========] Running 1 test from 1 test suite."
echo "[ RUN      ] Fake.Hangs"; echo "rendering..."
sleep 600
EOF
chmod +x "$tmp/bin/gl_tests" "$tmp/bin/image_tests"

# shellcheck disable=SC2054  # the commas are in the values
quick=(SWEEP_S=5 SWEEP_LIGHTS=256,1024,4096 SWEEP_SIZE=640x360 FRAMES=2
       COURTYARD_LIGHTS=64 COURTYARD_SIZE=96x54 LISTS_LIGHTS=64
       TESTS_S=5 TEST_SHARDS=8 TEST_BIN="$tmp/bin"
       LEARNOPENGL_LIGHTS=32 LEARNOPENGL_REPS=1 LOGL_PREBUILT="${LOGL_PREBUILT:-$tmp/empty}")
start=$(date +%s)
rc=0
env PATH="$tmp/marking:$PATH" ML="$ml" "${quick[@]}" scripts/gpu-report.sh --anyway --out "$tmp/2" \
  > "$tmp/2.out" 2> "$tmp/2.err" || rc=$?
r=$tmp/2/gpu-report.md
echo "(report with ML in $(($(date +%s) - start)) s)"
check "with ML: exit 0" [ "$rc" = 0 ]
check "... no make, apt-get, apt or sudo called" [ ! -e "$tmp/called" ]
for title in "Devices" "GPU (\`nvidia-smi\`, at the start)" "Tests" "Light sweep" "Courtyard table" \
             "Light lists" "Against LearnOpenGL" "GPU (\`nvidia-smi\`, at the end)"; do
  check "... section $title" has "$r" "## $title"
done
section "$r" Tests > "$tmp/tests.md"
check "tests: gl's row: 2 shards (a quarter of 8), 4 tests, 2 passed, 1 failed, 1 skipped" \
  has "$tmp/tests.md" "| gl | gl_tests | 2 | 4 | 2 | 1 | 1 | 0 |"
check "... the failure with its lines" has "$tmp/tests.md" "fake.cpp:12: Failure"
check "... the skip with its reason" has "$tmp/tests.md" "\`Fake.Skips\` (no GPU here)"
check "... image.gpu. with CMake's filter" grep -q 'gtest_filter=Scenes/TechniqueAgreement\.\*:' "$tmp/gpu-args"
check "... image's hanging test not finished, cut at the box" \
  has "$tmp/tests.md" "Not finished \`image.Fake.Hangs\` (cut at the time box)"
check "... the section says it was cut" has "$tmp/tests.md" "Cut at its time box of 5 s (TESTS_S)"
# 3. The sweep (21 cases at 640x360 on llvmpipe) cannot finish in 5 s.
section "$r" "Light sweep" > "$tmp/sweep.md"
check "sweep: cut at its time box of 5 s" has "$tmp/sweep.md" "Cut at its time box of 5 s"
check "... with the cases it finished" grep -q '^\[1/21\] forward 256 lights 640x360' "$tmp/sweep.md"
check "the courtyard table after it, with its GPU-timer table" \
  bash -c "awk '/^## Courtyard/,/^_/' '$r' | grep -q '^| technique | lights | size | frame_ms_median | .*_gpu_ms'"
check "the lists' two runs" [ "$(section "$r" "Light lists" | grep -c '^| clustered | 64 |')" = 2 ]
section "$r" "Against LearnOpenGL" > "$tmp/logl.md"
if [ -n "${LOGL_PREBUILT:-}" ]; then
  check "LearnOpenGL: compare.sh's table" has "$tmp/logl.md" "| 32 | manylights deferred |"
else
  check "LearnOpenGL: skipped, saying why" grep -q '^Skipped: ' "$tmp/logl.md"
fi

# 3b. The whole budget: after the tests' 5 s, under 5 s are left of TOTAL_S=9 for the rest.
env ML="$ml" "${quick[@]}" TOTAL_S=9 scripts/gpu-report.sh --anyway --out "$tmp/3" > /dev/null 2>&1 || true
check "TOTAL_S spent: the later sections say so" \
  [ "$(grep -c "^Skipped: under 5 s left of the report's budget (TOTAL_S=9 s)" "$tmp/3/gpu-report.md")" = 4 ]

# --- 4. stopped from outside during the sweep ---
mkdir -p "$tmp/4"
env ML="$ml" "${quick[@]}" SWEEP_S=120 scripts/gpu-report.sh --anyway --out "$tmp/4" > /dev/null 2> "$tmp/4.err" &
pid=$!
# Until the sweep has started, then stop it as a device call's limit or a Ctrl-C would.
for _ in $(seq 60); do grep -q 'Light sweep.* \.\.\.$' "$tmp/4.err" 2> /dev/null && break; sleep 0.5; done
sleep 2
kill -TERM "$pid"
rc=0; wait "$pid" || rc=$?
check "stopped: exit 143" [ "$rc" = 143 ]
check "... the tests section that finished is in the report" has "$tmp/4/gpu-report.md" "## Tests"
check "... the sweep says it was stopped" has "$tmp/4/gpu-report.md" "Stopped from outside during this section"
check "... no later section" bash -c "! grep -q '## Courtyard' '$tmp/4/gpu-report.md'"
sleep 1   # the bench's timeout passes the signal on
# (swee[p]: the pattern must not match the command line of the bash that runs pgrep)
check "... nothing of it left running (its bench)" bash -c "! pgrep -f -- '$tmp/4/swee[p]' > /dev/null"

echo "$passes passed, $failures failed"
[ "$failures" = 0 ]
