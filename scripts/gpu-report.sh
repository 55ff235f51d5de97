#!/usr/bin/env bash
# The measurements on a hardware GPU (issues 30 and 40), as one markdown report naming the
# device, the driver and the GPU's clocks: the GL, image and unit tests on it, the light sweep at
# 1920x1080 (1,024 to 1,048,576 lights, every technique within a frame budget), the courtyard
# table of docs/performance.md (1280x720), every light shadowed through the shadow-page pool
# (1920x1080: unshadowed, cached, rebuilt), the light lists from bit masks against sorted ones,
# and the LearnOpenGL comparison (../shared/peer/learnopengl-8.1/compare.sh, headless).
#
# It is made for a bare GPU server (no package registry, nothing installable): given a prebuilt
# executable (ML=...) it builds nothing and installs nothing. Every section has a time box and
# the whole report a budget (TOTAL_S, default 300 s); each section is appended to the report as
# it finishes, so a run cut short keeps what it measured, and a section cut at its box says so.
#
# Usage: [ML=path/to/manylights] scripts/gpu-report.sh [--anyway] [--device N] [--out DIR]
#   --anyway    run on a software rasteriser too (llvmpipe); without it the script says that
#               there is no GPU here and stops (exit 1), as the figures would be llvmpipe's
#   --device N  the EGL device to measure (manylights devices lists them; default: the
#               renderer's own choice, hardware first). The tests use the default device.
#   --out DIR   where the report (DIR/gpu-report.md) and the raw outputs go (default out/gpu-report)
# Executables, from the environment (relative paths are from the project root):
#   ML=FILE       a prebuilt manylights: then nothing is built or installed. Without ML it runs
#                 `make build` (scripts/setup.sh, apt) and uses build/manylights; if that fails
#                 it says so in one line and exits 1.
#   TEST_BIN=DIR  the prebuilt gl_tests, image_tests and unit_tests (default: $(dirname ML)/tests)
#   LOGL_KIT=DIR  the LearnOpenGL kit (default ../shared/peer/learnopengl-8.1)
#   LOGL_PREBUILT=DIR  its `deferred` program built elsewhere (the kit's README); without it the
#                 kit's build.sh compiles it where its headers are installed, else the section
#                 says "skipped" (the kit's install-deps.sh is never run)
# Time boxes in seconds (each cut to what is left of TOTAL_S=300):
#   TESTS_S=90  SWEEP_S=60  COURTYARD_S=40  SHADOWS_S=40  LISTS_S=30  LEARNOPENGL_S=90  SETUP_S=30 (each of
#   `manylights devices`, nvidia-smi and the probe render)
# Settings, for a quicker look:
#   SWEEP_LIGHTS=1024,4096,16384,65536,262144,1048576  SWEEP_SIZE=1920x1080
#   COURTYARD_LIGHTS=256,1024,4096,16384,65536  COURTYARD_SIZE=1280x720  LISTS_LIGHTS=1024,4096,16384
#   SHADOW_LIGHTS=1024,4096,65536 (every light shadowed, at SWEEP_SIZE)
#   FRAMES=5  BUDGET_MS=250 (a technique's larger light counts are skipped once its median frame
#   passes this: on an H100 forward takes 2.9 s a frame at 16,384 lights at 1080p)
#   TEST_SHARDS=$(nproc) (processes for the tests, all suites together)
#   LEARNOPENGL_LIGHTS="32 128 512"  LEARNOPENGL_REPS=2
#   COST_LIGHTS=16384,1048576  COST_FRAMES=20 (the per-pass queries' cost: --pass-timing gpu
#   against frame, at SWEEP_SIZE; PROFILER_COST_S=30)
#   REFERENCE_DIR=DIR  forward against llvmpipe's forward: the PFMs scripts/make-llvmpipe-
#   references.sh made on llvmpipe (REFERENCE_S=40); without it the section is left out
#   TESTS=1 SWEEP=1 COURTYARD=1 SHADOWS=1 MASKED_LISTS=1 PROFILER_COST=1 LEARNOPENGL=1 (0 skips a section)
# On a lent GPU machine: ../shared/gpu/README.md (make-kit.sh, then ML=build/manylights through
# .gpu-kit/on-device.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

anyway=0
device=()
out=out/gpu-report
while [ $# -gt 0 ]; do
  case "$1" in
    --anyway) anyway=1 ;;
    --device) device=(--device "$2"); shift ;;
    --out) out=$2; shift ;;
    *) echo "usage: [ML=path/to/manylights] scripts/gpu-report.sh [--anyway] [--device N] [--out DIR]" >&2; exit 2 ;;
  esac
  shift
done
sweep_lights=${SWEEP_LIGHTS:-1024,4096,16384,65536,262144,1048576}
sweep_size=${SWEEP_SIZE:-1920x1080}
courtyard_lights=${COURTYARD_LIGHTS:-256,1024,4096,16384,65536}
courtyard_size=${COURTYARD_SIZE:-1280x720}
shadow_lights=${SHADOW_LIGHTS:-1024,4096,65536}
lists_lights=${LISTS_LIGHTS:-1024,4096,16384}
frames=${FRAMES:-5}
cost_lights=${COST_LIGHTS:-16384,1048576}
cost_frames=${COST_FRAMES:-20}
budget=${BUDGET_MS:-250}
learnopengl_lights=${LEARNOPENGL_LIGHTS:-32 128 512}
learnopengl_reps=${LEARNOPENGL_REPS:-2}
shards_total=${TEST_SHARDS:-$(nproc)}
setup_s=${SETUP_S:-30}
mkdir -p "$out"
out=$(cd "$out" && pwd)   # absolute: the tests and compare.sh run in other folders
report=$out/gpu-report.md
sec=$out/section.md.part
rm -f "$report" "$sec"    # a report left from an earlier run is not this one's

# The executable: a prebuilt one as given, else today's build, which needs a package registry.
if [ -n "${ML:-}" ]; then
  if [ ! -f "$ML" ] || [ ! -x "$ML" ]; then echo "gpu-report: ML=$ML is not an executable file" >&2; exit 1; fi
  ml=$(cd "$(dirname "$ML")" && pwd)/$(basename "$ML")
  built="prebuilt (ML=$ML)"
else
  if ! make build > "$out/build.log" 2>&1; then
    echo "gpu-report: make build failed (output in $out/build.log); where nothing can be built or installed, give a prebuilt executable: ML=path/to/manylights scripts/gpu-report.sh" >&2
    exit 1
  fi
  ml=$PWD/build/manylights
  built="built here by make build"
fi
test_bin=${TEST_BIN:-$(dirname "$ml")/tests}
test_bin=$(cd "$test_bin" 2>/dev/null && pwd || echo "$test_bin")

# The budget starts after the build: the five minutes are the GPU server's, which builds nothing.
total_s=${TOTAL_S:-300}
report_start=$(date +%s)
deadline=$((report_start + total_s))

# box_for VAR DEFAULT: the seconds a section may run, its own box ($VAR, else DEFAULT) cut to
# what is left of TOTAL_S; 0 when under 5 s are left (the section then says it was skipped).
box_for() {
  local want=${!1:-$2} left=$((deadline - $(date +%s)))
  [[ "$want" =~ ^[0-9]+$ ]] || { echo "gpu-report: $1=$want is not a number of seconds" >&2; exit 2; }
  [ "$left" -lt "$want" ] && want=$left
  [ "$want" -lt 5 ] && want=0
  echo "$want"
}
# boxed SECONDS CMD...: CMD under `timeout`, status 124 (or 137 after the KILL) when its box
# expired. timeout signals its whole process group, so what CMD started (the manylights processes
# of image_tests, compare.sh's runs) stops with it. Started in the background and waited for, so
# that a signal to this script is handled at once (stop, below), not after CMD.
children=()
boxed() {
  local s=$1 rc=0; shift
  timeout -k 10 "$s" "$@" &
  children=($!)
  wait "${children[0]}" || rc=$?
  children=()
  return "$rc"
}
timed_out() { [ "$1" = 124 ] || [ "$1" = 137 ]; }
# Each timeout is a process group of its own, out of reach of a Ctrl-C or a signal to this
# script's group: pass the signal on, so that a report stopped from outside leaves nothing
# running, and say in the report where it stopped.
stop() {
  trap - TERM INT HUP
  [ ${#children[@]} -gt 0 ] && kill -TERM "${children[@]}" 2> /dev/null
  if [ -n "${sec_title:-}" ] && [ -f "$report" ]; then
    printf '\n## %s\n\n**Stopped from outside during this section.**\n' "$sec_title" >> "$report"
  fi
  echo "gpu-report: stopped; $report has the sections that finished" >&2
  exit 143
}
trap stop TERM INT HUP

# Each section is written to $sec, then appended to the report when it is done.
begin() {
  sec_title=$1 sec_start=$(date +%s)
  printf '\n## %s\n\n' "$1" > "$sec"
  echo "gpu-report: $1 ..." >&2
}
say() { printf '%s\n' "$*" >> "$sec"; }
fence() { { echo '```'; cat "$@"; echo '```'; } >> "$sec"; }
end() {
  local took=$(($(date +%s) - sec_start))
  printf '\n_%s s._\n' "$took" >> "$sec"
  cat "$sec" >> "$report"
  rm -f "$sec"
  echo "gpu-report: $sec_title: $took s" >&2
  sec_title=
}
# no_time VAR: the section's box is 0: it says so and ends.
no_time() {
  say "Skipped: under 5 s left of the report's budget (TOTAL_S=$total_s s) for its box ($1)."
  end
}

# Where the driver tells them: the GPU's name, driver and clocks (run at the start and the end,
# since the clocks move with load and temperature).
gpu_clocks() {
  if command -v nvidia-smi > /dev/null 2>&1; then
    boxed "$setup_s" nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem,clocks.max.sm,clocks.max.mem,temperature.gpu,power.draw \
      --format=csv 2>&1 || echo "(nvidia-smi failed: status $?)"
  else
    echo "none: no nvidia-smi on this machine, so no driver that tells its GPU's clocks"
  fi
}

# --- The device, the driver, the machine ----------------------------------------------------------
devices=$(boxed "$setup_s" "$ml" devices 2>&1 || true)
clocks=$(gpu_clocks)
# What the renderer runs on with these options: its --stats name it.
if ! boxed "$setup_s" "$ml" render -o "$out/probe.png" --size 64x36 --stats "$out/probe.json" "${device[@]}" \
     > "$out/probe.log" 2>&1; then
  echo "gpu-report: $ml could not render (output in $out/probe.log): $(tail -n 1 "$out/probe.log")" >&2
  exit 1
fi
renderer=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["device"])' "$out/probe.json")
profile=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["driver_profile"])' "$out/probe.json")
if [ "$profile" = software ]; then
  echo "gpu-report: $renderer is a software rasteriser, not a GPU: nothing to report here" >&2
  if [ "$anyway" = 0 ]; then
    echo "gpu-report: on a GPU server pick its device (--device N; manylights devices lists them)," \
         "or run anyway with --anyway" >&2
    exit 1
  fi
fi
# The commit: git's, else the kit's (make-kit.sh writes it; a device run has no .git).
commit=$(git rev-parse --short HEAD 2>/dev/null ||
         cat "$(dirname "$(readlink -f "$ml")")/../commit" 2>/dev/null || true)
[ -n "$commit" ] || commit=unknown

{
  echo "# manylights on $renderer"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, driver profile \`$profile\`$([ "$profile" = software ] &&
        echo ' (a software rasteriser: run with --anyway, not GPU figures)')."
  echo "Machine: $(nproc) CPU cores, $(uname -sr). Executable: $ml, $built."
  echo
  echo "## Devices (\`manylights devices\`)"
  echo
  echo '```'
  echo "$devices"
  echo '```'
  echo
  echo "## GPU (\`nvidia-smi\`, at the start)"
  echo
  echo '```'
  echo "$clocks"
  echo '```'
} > "$report"

# --- Tests ------------------------------------------------------------------------------------------
# gtest_summary MANIFEST: the markdown summary of sharded gtest runs. MANIFEST has one line per
# shard: suite, program, output file, exit status. The per-test lines are read, not gtest's final
# summary, so a shard cut at its box or crashed still counts what it finished.
gtest_summary() {
  python3 - "$1" <<'PY'
import re, sys
suites = {}   # suite -> {program, shards, passed, failed: [(name, lines)], skipped, unfinished, cut}
for line in open(sys.argv[1]):
    suite, program, path, rc = line.split()
    s = suites.setdefault(suite, {"program": program, "shards": 0, "passed": 0, "failed": [],
                                  "skipped": [], "unfinished": [], "cut": 0, "crashed": 0, "total": 0})
    s["shards"] += 1
    rc = int(rc)
    s["cut"] += rc in (124, 137)
    s["crashed"] += rc not in (0, 1, 124, 137)
    current, lines = None, []
    for text in open(path, errors="replace"):
        text = text.rstrip("\n")
        m = re.match(r"\[==========\] Running (\d+) tests? ", text)
        if m:
            s["total"] += int(m.group(1))
        m = re.match(r"\[ RUN      \] (.*)$", text)
        if m:
            current, lines = m.group(1), []
            continue
        if current is None:
            continue
        m = re.match(r"\[ {7}OK \] |\[  FAILED  \] |\[  SKIPPED \] ", text)
        if m and text[13:].startswith(current):
            if "OK" in m.group(0):
                s["passed"] += 1
            elif "FAILED" in m.group(0):
                s["failed"].append((current, lines))
            else:
                why = next((l for i, l in enumerate(lines) if i and lines[i - 1].endswith(": Skipped")), "")
                s["skipped"].append((current, why))
            current = None
        else:
            lines.append(text)
    if current is not None:
        fate = "cut at the time box" if rc in (124, 137) else "shard ended with status %d" % rc
        s["unfinished"].append((current, fate, [l for l in lines if l.strip()][-8:]))
print("| suite | program | shards | tests | passed | failed | skipped | not finished |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for name, s in suites.items():
    note = []
    if s["cut"]:
        note.append("%d cut at the time box" % s["cut"])
    if s["crashed"]:
        note.append("%d crashed" % s["crashed"])
    print("| %s | %s | %d%s | %d | %d | %d | %d | %d |" % (name, s["program"], s["shards"],
          " (%s)" % ", ".join(note) if note else "", s["total"], s["passed"], len(s["failed"]),
          len(s["skipped"]), len(s["unfinished"])))
for name, s in suites.items():
    for test, lines in s["failed"]:
        print("\nFAILED `%s.%s`:\n\n```" % (name, test))
        shown = [l for l in lines if l.strip()]
        print("\n".join(shown[:25] + (["... (%d more lines)" % (len(shown) - 25)] if len(shown) > 25 else [])))
        print("```")
    for test, fate, lines in s["unfinished"]:
        print("\nNot finished `%s.%s` (%s)%s" % (name, test, fate,
              "; its last lines:\n\n```\n%s\n```" % "\n".join(lines) if lines else "."))
    if s["skipped"]:
        print("\nSkipped in %s: %s" % (name, "; ".join("`%s`%s" % (t, " (%s)" % w if w else "") for t, w in s["skipped"])))
PY
}

# The image.gpu. suite as CTest runs it: its filter and environment from tests/CMakeLists.txt,
# so that the two stay one definition. Prints "FILTER ENV" or nothing.
gpu_suite_from_cmake() {
  python3 - tests/CMakeLists.txt <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for call in re.findall(r"gtest_discover_tests\((.*?)\)", text, re.S):
    if 'TEST_PREFIX "image.gpu."' in call:
        f = re.search(r'TEST_FILTER\s+"([^"]+)"', call)
        e = re.search(r"ENVIRONMENT\s+(\S+=\S+)", call)
        if f and e:
            print(f.group(1), e.group(1))
PY
}

# The folder the tests were compiled against (MANYLIGHTS_SOURCE_DIR, read from the program): the
# scenes and goldens they read. Where it is not this tree, on-device.sh links it.
compiled_source_dir() {
  python3 - "$1" <<'PY'
import re, sys
m = re.search(rb"\x00(/[\x21-\x7e]*?)/tests/scenes/", open(sys.argv[1], "rb").read())
print(m.group(1).decode() if m else "")
PY
}

if [ "${TESTS:-1}" = 1 ]; then
  begin "Tests: unit, GL and image tests (prebuilt, sharded)"
  box=$(box_for TESTS_S 90)
  if [ "$box" = 0 ]; then no_time TESTS_S
  elif [ ! -x "$test_bin/gl_tests" ] || [ ! -x "$test_bin/image_tests" ]; then
    say "Skipped: no gl_tests and image_tests in $test_bin (TEST_BIN)."
    end
  else
    # suite, program, shards, gtest filter, environment: as tests/CMakeLists.txt defines them.
    # The shards split the cores by each suite's weight (image tests are the longest).
    share() { local n=$((shards_total * $1 / 8)); [ "$n" -lt 1 ] && n=1; echo "$n"; }
    suites=("gl gl_tests $(share 2) * -" "image image_tests $(share 4) * -")
    read -r gpu_filter gpu_env <<< "$(gpu_suite_from_cmake)" || true
    if [ -n "${gpu_filter:-}" ]; then
      suites+=("image.gpu image_tests $(share 2) $gpu_filter $gpu_env")
    else
      say "The image.gpu. suite is missing: no TEST_PREFIX \"image.gpu.\" with a filter and environment in tests/CMakeLists.txt."
    fi
    [ -x "$test_bin/unit_tests" ] && suites=("unit unit_tests 1 * -" "${suites[@]}")
    src=$(compiled_source_dir "$test_bin/image_tests")
    say "From $test_bin, $box s time box. Suites as CTest names them (tests/CMakeLists.txt): image.gpu." \
        "is image_tests with \`${gpu_env:-?}\` and its filter. Each shard runs in $out/tests/work" \
        "(CTest runs them in the build's tests folder; they write only test-output/ there)." \
        "image_tests runs the manylights executable it was compiled with, not ML."
    if [ -n "$src" ] && [ ! -d "$src/tests/scenes" ]; then
      say
      say "**The tests were compiled against $src (MANYLIGHTS_SOURCE_DIR), which is not here: they cannot" \
          "find their scenes. Link it to this tree (on-device.sh does).**"
    fi
    mkdir -p "$out/tests/work"
    rm -f "$out"/tests/*.txt
    manifest=$out/tests/manifest
    : > "$manifest"
    pids=() files=()
    for s in "${suites[@]}"; do
      read -r name prog n filter envv <<< "$s"
      env_args=(GTEST_COLOR=no)
      [ "$envv" != - ] && env_args+=("$envv")
      for ((i = 0; i < n; i++)); do
        f=$out/tests/$name-$i.txt
        (cd "$out/tests/work" && exec env "${env_args[@]}" GTEST_TOTAL_SHARDS="$n" GTEST_SHARD_INDEX="$i" \
           timeout -k 10 "$box" "$test_bin/$prog" --gtest_filter="$filter") > "$f" 2>&1 &
        pids+=($!) files+=("$name $prog $f")
      done
    done
    # Explicit PIDs: a bare `wait` also waits for any process substitution of the caller's.
    children=("${pids[@]}")
    for k in "${!pids[@]}"; do
      rc=0; wait "${pids[$k]}" || rc=$?
      echo "${files[$k]} $rc" >> "$manifest"
    done
    children=()
    say
    gtest_summary "$manifest" >> "$sec"
    if grep -Eq ' (124|137)$' "$manifest"; then
      say; say "**Cut at its time box of $box s (TESTS_S)**: the counts are of the tests that finished."
    fi
    say; say "Each shard's output: $out/tests/SUITE-I.txt."
    end
  fi
fi

# --- Benchmarks -------------------------------------------------------------------------------------
# gpu_table CSV: bench's CSV as a markdown table of the wall frame time and every GPU-timer
# column it has, picked by name (`*_gpu_ms`, with or without `_median`), so that new per-pass
# columns show up without a change here. Columns empty in every row are left out.
gpu_table() {
  python3 - "$1" <<'PY'
import csv, re, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
if not rows:
    print("(the CSV has no rows)")
    sys.exit()
cols = list(rows[0].keys())
wall = [c for c in cols if re.fullmatch(r"frame_ms(_median)?", c) or re.search(r"_wall_ms(_median)?$", c)]
gpu = [c for c in cols if re.search(r"_gpu_ms(_median)?$", c)]
keep = [c for c in wall + gpu if any(r.get(c) for r in rows)]
if not any(c in gpu for c in keep):
    print("The CSV has no `*_gpu_ms` column with values (no GL timer queries?).")
    sys.exit()
print("From the CSV: wall clock (`%s`) and GL timer queries (`%s`), ms."
      % ("`, `".join(c for c in keep if c in wall), "`, `".join(c for c in keep if c in gpu)))
print()
print("| technique | lights | size | " + " | ".join(keep) + " |")
print("|---|---:|---|" + "---:|" * len(keep))
for r in rows:
    size = "%sx%s" % (r.get("width", "?"), r.get("height", "?"))
    print("| %s | %s | %s | %s |" % (r.get("technique", ""), r.get("lights", ""), size,
                                    " | ".join(r.get(c) or "-" for c in keep)))
PY
}

# run_bench NAME SECONDS [env VAR=VALUE ...] -- BENCH_ARGS...: one `manylights bench` under its
# box into $out/NAME.{txt,csv,log}, and its results into the section: bench's table (the passes'
# wall times) and the GPU-timer table; cut at the box, the cases it finished (its progress lines).
run_bench() {
  local name=$1 s=$2 rc=0; shift 2
  local pre=()
  while [ "$1" != -- ]; do pre+=("$1"); shift; done
  shift
  rm -f "$out/$name.csv"
  boxed "$s" "${pre[@]}" "$ml" bench "$@" --csv "$out/$name.csv" "${device[@]}" \
    > "$out/$name.txt" 2> "$out/$name.log" || rc=$?
  if [ "$rc" = 0 ]; then
    fence "$out/$name.txt"
    if grep -q 'skipped' "$out/$name.log"; then
      say; say "Over the budget ($budget ms), not measured: $(grep 'skipped' "$out/$name.log" |
        sed -E 's/^\[[0-9/]+\] ([^:]*): .*/\1/' | paste -sd ';' | sed 's/;/; /g')."
    fi
    say; gpu_table "$out/$name.csv" >> "$sec"
  elif timed_out "$rc"; then
    say "**Cut at its time box of $s s**: the cases it finished (bench's progress lines; no CSV):"
    say; grep -E '^\[[0-9]+/[0-9]+\]' "$out/$name.log" > "$out/$name.progress" || true
    fence "$out/$name.progress"
  else
    say "bench failed (exit $rc; $out/$name.log):"
    say; tail -n 5 "$out/$name.log" > "$out/$name.tail"; fence "$out/$name.tail"
  fi
}

if [ "${SWEEP:-1}" = 1 ]; then
  begin "Light sweep: bench/courtyard.json at $sweep_size"
  box=$(box_for SWEEP_S 60)
  if [ "$box" = 0 ]; then no_time SWEEP_S; else
    say "Every technique at ${sweep_lights//,/, } lights, $frames frames after one warm-up frame;" \
        "a technique whose median frame passes $budget ms skips its larger counts. Time box $box s" \
        "(SWEEP_S). Plot: $out/sweep.svg."
    say
    run_bench sweep "$box" -- bench/courtyard.json --lights "$sweep_lights" --size "$sweep_size" \
      --frames "$frames" --budget-ms "$budget" --plot "$out/sweep.svg"
    end
  fi
fi

if [ "${COURTYARD:-1}" = 1 ]; then
  begin "Courtyard table (docs/performance.md) at $courtyard_size"
  box=$(box_for COURTYARD_S 40)
  if [ "$box" = 0 ]; then no_time COURTYARD_S; else
    say "Every technique at ${courtyard_lights//,/, } lights, $frames frames, budget $budget ms, time box $box s (COURTYARD_S)."
    say
    run_bench courtyard "$box" -- bench/courtyard.json --lights "$courtyard_lights" --size "$courtyard_size" \
      --frames "$frames" --budget-ms "$budget"
    end
  fi
fi

if [ "${SHADOWS:-1}" = 1 ]; then
  # Issue 47: every light shadowed through the shadow-page pool (docs/shadows.md, "What it
  # costs"), the llvmpipe table's three rows at the sweep's size: unshadowed, every light
  # shadowed with its pages cached (a still scene), and every page marked and drawn each frame.
  begin "Every light shadowed (the shadow-page pool) at $sweep_size"
  box=$(box_for SHADOWS_S 40)
  if [ "$box" = 0 ]; then no_time SHADOWS_S; else
    say "\`clustered\` on the courtyard at ${shadow_lights//,/, } lights: unshadowed, \`--shadow-lights all\`" \
        "with cached pages, and with \`--rebuild-shadows\`; the \`shadow*\` passes in bench's table." \
        "Time box $box s (SHADOWS_S), a third for each."
    for mode in none cached rebuilt; do
      case "$mode" in
        none) extra=() ;;
        cached) extra=(--shadow-lights all) ;;
        rebuilt) extra=(--shadow-lights all --rebuild-shadows) ;;
      esac
      say; say "Shadows: $mode"; say
      run_bench "shadows-$mode" $((box / 3)) -- bench/courtyard.json --techniques clustered \
        --lights "$shadow_lights" --size "$sweep_size" --frames "$frames" "${extra[@]}"
    done
    end
  fi
fi

if [ "${MASKED_LISTS:-1}" = 1 ]; then
  # The limit kMaskedListLights was chosen on llvmpipe (docs/techniques.md: the lists from bit
  # masks); on a GPU the masks' atomics against the sort are still to be measured.
  begin "Light lists from bit masks against sorted pairs at $courtyard_size"
  box=$(box_for LISTS_S 30)
  if [ "$box" = 0 ]; then no_time LISTS_S; else
    say "\`tiled\` and \`clustered\` at ${lists_lights//,/, } lights with their lists from bit masks" \
        "(the default), then sorted (MANYLIGHTS_MASKED_LIST_LIGHTS=0); \`--classic\`. Time box $box s" \
        "(LISTS_S), half for each."
    for limit in default 0; do
      if [ "$limit" = default ]; then pre=(); else pre=(env MANYLIGHTS_MASKED_LIST_LIGHTS=0); fi
      say; say "Lists: $([ "$limit" = default ] && echo 'from bit masks' || echo 'sorted')"; say
      run_bench "lists-$limit" $((box / 2)) "${pre[@]}" -- bench/courtyard.json --techniques clustered,tiled \
        --lights "$lists_lights" --size "$courtyard_size" --frames "$frames" --classic
    done
    end
  fi
fi

if [ "${PROFILER_COST:-1}" = 1 ]; then
  # The per-pass timer queries' own cost (docs/performance.md, "Timing on a GPU"): the same
  # frames with them (--pass-timing gpu) and with only the frame's two timestamps (frame).
  begin "What the per-pass queries cost: --pass-timing gpu against frame at $sweep_size"
  box=$(box_for PROFILER_COST_S 30)
  if [ "$box" = 0 ]; then no_time PROFILER_COST_S; else
    say "\`tiled\` and \`clustered\` at ${cost_lights//,/, } lights, $cost_frames frames issued back to back," \
        "with the per-pass queries, then without. Time box $box s (PROFILER_COST_S), half for each."
    for timing in gpu frame; do
      say; say "--pass-timing $timing"; say
      run_bench "cost-$timing" $((box / 2)) -- bench/courtyard.json --techniques tiled,clustered \
        --lights "$cost_lights" --size "$sweep_size" --frames "$cost_frames" --pass-timing "$timing"
    done
    end
  fi
fi

if [ -n "${REFERENCE_DIR:-}" ]; then
  # forward here against forward on llvmpipe (scripts/make-llvmpipe-references.sh made the
  # references, with --anisotropy 1 and the software profile): docs/testing.md says what may
  # differ, and this is how much does.
  begin "forward against llvmpipe's forward (--anisotropy 1)"
  box=$(box_for REFERENCE_S 40)
  if [ "$box" = 0 ]; then no_time REFERENCE_S
  elif [ ! -f "$REFERENCE_DIR/scenes.txt" ]; then
    say "Skipped: $REFERENCE_DIR has no scenes.txt (scripts/make-llvmpipe-references.sh makes it)."
    end
  else
    say "References from $(cat "$REFERENCE_DIR/device.txt" 2> /dev/null || echo 'an unnamed device'); each scene at" \
        "320x180, forward, --anisotropy 1, here with this device's profile. Time box $box s (REFERENCE_S)."
    say
    : > "$out/references.txt"
    refs_deadline=$(($(date +%s) + box))
    while read -r name scene; do
      left=$((refs_deadline - $(date +%s)))
      [ "$left" -lt 2 ] && { echo "$name: not compared, the time box ran out" >> "$out/references.txt"; continue; }
      # shellcheck disable=SC2086 # the scene is one word or none
      if boxed "$left" "$ml" render $scene -o "$out/forward-$name.pfm" --size 320x180 --technique forward \
           --anisotropy 1 "${device[@]}" > "$out/forward-$name.log" 2>&1; then
        python3 scripts/compare-pfm.py "$REFERENCE_DIR/$name.pfm" "$out/forward-$name.pfm" "$name" \
          >> "$out/references.txt" 2>&1 || true
      else
        echo "$name: render failed ($out/forward-$name.log)" >> "$out/references.txt"
      fi
    done < "$REFERENCE_DIR/scenes.txt"
    fence "$out/references.txt"
    end
  fi
fi

# --- LearnOpenGL 8.1 --------------------------------------------------------------------------------
# Its program as the kit takes it: LOGL_PREBUILT, else built by the kit's build.sh where the
# headers it names are installed (compiling only; the kit's install-deps.sh would call apt).
logl_program() {
  local kit=$1
  if [ -n "${LOGL_PREBUILT:-}" ]; then
    [ -x "$LOGL_PREBUILT/deferred" ] || { echo "skipped: LOGL_PREBUILT=$LOGL_PREBUILT has no deferred program"; return 1; }
    (cd "$LOGL_PREBUILT" && pwd)
    return 0
  fi
  local h missing=()
  for h in GLFW/glfw3.h glm/glm.hpp assimp/Importer.hpp stb/stb_image.h stb/stb_image_write.h; do
    [ -e "/usr/include/$h" ] || missing+=("$h")
  done
  command -v g++ > /dev/null 2>&1 || missing+=(g++)
  if [ ${#missing[@]} -gt 0 ]; then
    echo "skipped: no prebuilt LearnOpenGL program (LOGL_PREBUILT) and it cannot be built here (missing: ${missing[*]}; nothing is installed)"
    return 1
  fi
  "$kit/build.sh" 2> "$out/learnopengl-build.log" ||
    { echo "skipped: the kit's build.sh failed ($out/learnopengl-build.log)"; return 1; }
}

if [ "${LEARNOPENGL:-1}" = 1 ]; then
  begin "Against LearnOpenGL 8.1 (compare.sh, 800x600, headless)"
  box=$(box_for LEARNOPENGL_S 90)
  kit=${LOGL_KIT:-../shared/peer/learnopengl-8.1}
  if [ "$box" = 0 ]; then no_time LEARNOPENGL_S
  elif [ ! -x "$kit/compare.sh" ]; then
    say "Skipped: no LearnOpenGL kit at $kit (LOGL_KIT)."
    end
  elif ! logl=$(logl_program "$kit"); then
    say "${logl^}."
    end
  else
    # Both sides headless (LOGL_EGL=1, no Xvfb); on a GPU, KIT_GPU=1 keeps both off Mesa's software
    # rasteriser. LOGL_PREBUILT makes the kit's install-deps.sh and build.sh do nothing.
    kit_gpu=0; [ "$profile" = software ] || kit_gpu=1
    say "Lights ${learnopengl_lights// /, }, $frames frames, REPS=$learnopengl_reps; LOGL_EGL=1 KIT_GPU=$kit_gpu," \
        "LearnOpenGL program from $logl; time box $box s (LEARNOPENGL_S)."
    say
    rc=0
    # shellcheck disable=SC2086  # the light counts are separate arguments
    boxed "$box" env LOGL_PREBUILT="$logl" LOGL_EGL=1 KIT_GPU=$kit_gpu ML="$ml" OUT_DIR="$out/learnopengl" \
      REPS="$learnopengl_reps" "$kit/compare.sh" $learnopengl_lights "$frames" \
      > "$out/learnopengl.out" 2> "$out/learnopengl.log" || rc=$?
    if timed_out "$rc"; then
      say "**Cut at its time box of $box s**: the runs it finished (compare.sh's progress lines):"
      say; grep -E '^  \[' "$out/learnopengl.log" > "$out/learnopengl.progress" || true
      fence "$out/learnopengl.progress"
    elif grep -q '^LearnOpenGL 8.1' "$out/learnopengl.out"; then
      # Its table, without anything printed before it.
      sed -n '/^LearnOpenGL 8.1/,$p' "$out/learnopengl.out" > "$out/learnopengl.txt"
      fence "$out/learnopengl.txt"
      [ "$rc" = 0 ] || { say; say "Some runs failed (marked fail; logs in $out/learnopengl)."; }
    else
      say "compare.sh failed (exit $rc; $out/learnopengl.log):"
      say; tail -n 5 "$out/learnopengl.log" > "$out/learnopengl.tail"; fence "$out/learnopengl.tail"
    fi
    end
  fi
fi

{
  echo
  echo "## GPU (\`nvidia-smi\`, at the end)"
  echo
  echo '```'
  gpu_clocks
  echo '```'
  echo
  echo "Report written in $(($(date +%s) - report_start)) s of its $total_s s budget (TOTAL_S)."
} >> "$report"
echo "gpu-report: wrote $report" >&2
