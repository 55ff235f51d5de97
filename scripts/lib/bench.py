#!/usr/bin/env python3
"""The measurement harness of the scripts/measure-*.sh scripts (docs/performance.md, "How the
figures are taken").

A measurement is a set of cases, each one `manylights bench` (or `render --stats`) command line
with its own environment and binary. Every round runs every case once, the order rotated by one
case each round, so that a load that changes during the run meets the cases alike (interleaved
A/B rounds). bench's `--json` gives every pass with the clock it was timed on (its wall time
under --pass-timing wall, its GL_TIME_ELAPSED under gpu), so nothing here knows which clock a
driver profile implies. First and last it prints the machine: CPU model, cores, the load average
at the start and at the end, the GL renderer, the commit and the binaries.

Used from the shell (scripts/measure-*.sh):

    scripts/lib/bench.py --rounds 3 --frames 9 --column cpu-culling --compare \\
        --case '1 thread: MANYLIGHTS_CULLING_THREADS=1 bench/courtyard.json --techniques tiled-quads' \\
        --case '2 threads: MANYLIGHTS_CULLING_THREADS=2 bench/courtyard.json --techniques tiled-quads'

A case is 'LABEL: [NAME=VALUE ...] [render] ARGUMENTS': NAME=VALUE words set the environment of
that command (ML=PATH runs another binary), `render` makes it a `manylights render --stats`
command instead of a bench one (for what is measured outside bench's frames: load times, start-up
memory). A label is SERIES or SERIES/POINT: --compare divides the first series' figures by the
second's, row by row; --per-pair divides a column's change across one series' light counts (or
points) by the change of its light evaluations.

A column is NAME=EXPRESSION or an EXPRESSION that names itself: terms joined by ' + ' or ' - '
(spaces around), optionally over a second such sum after ' / '; a term may be a product of
figures joined by ' * ' (a pass's time among them). A figure is a pass's median time
on the clock its frames were timed with (a pass name; shell-style wildcards sum several:
'shadow*'), `invocations.PASS` (its fragment invocations), `frame` (the median frame), `gpu frame`
(between GL_TIMESTAMPs), `counter.NAME` (a technique counter), `work.NAME` (--count-work's
counts), `stat.NAME` (a number of render --stats, or of bench's row: warmup_frames), `lights`,
`pixels`, `peak rss` (the process's peak resident memory, bytes), `process s` (the whole command's
seconds) or a number. A pass that a row does not have counts 0 as long as one of the sum's
passes is there.

A build from before bench had --json (issue 46) is read from its --csv instead, so that OLD=
comparisons reach back: its passes' times are those of the CSV's pass_timing column (wall where
it has none), and it has no counters.

Environment: ML the binary (default build/manylights, built with `make app` when absent),
BENCH_ARGS more arguments for every command (e.g. '--driver-profile gpu').
"""

import argparse
import csv
import datetime
import fnmatch
import json
import os
import re
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# --- the machine ------------------------------------------------------------------------------


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def commit():
    """The checkout's commit, and whether files differ from it."""
    try:
        head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return head + (" with uncommitted changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown (not a git checkout)"


def machine_header(binaries):
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [f"machine: {cpu_model()}, {os.cpu_count()} cores, load average {load_average()} at the start, {now}",
             f"commit: {commit()}"]
    lines += [f"binary: {b}" for b in binaries]
    return "\n".join(lines)


def gl_line(document):
    """What bench's --json (or render's --stats) says about the GL driver and the clocks."""
    renderer = document.get("gl_renderer") or document.get("device", "unknown")
    version = document.get("gl_version")
    text = f"GL: {renderer}" + (f", {version}" if version else "")
    if "driver_profile" in document:
        text += f"; driver profile {document['driver_profile']}"
    if "pass_timing" in document:
        text += f"; pass timing {document['pass_timing']}"
    return text


# --- running cases ----------------------------------------------------------------------------


class Case:
    """One command line of a measurement: 'LABEL: [NAME=VALUE ...] [render] ARGUMENTS'."""

    def __init__(self, spec, binary):
        label, separator, rest = spec.partition(":")
        if not separator or not label.strip():
            raise ValueError(f"case '{spec}': expected 'LABEL: ARGUMENTS'")
        self.label = label.strip()
        self.series, _, self.point = self.label.partition("/")
        words = shlex.split(rest)
        self.environment = {}
        while words and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=.*", words[0]):
            name, value = words.pop(0).split("=", 1)
            self.environment[name] = value
        self.binary = self.environment.pop("ML", binary)
        self.render = bool(words) and words[0] == "render"
        self.arguments = words[1:] if self.render else words

    def command(self, output, frames, warmup, extra, json_output=True):
        if self.render:
            # render --frames times after one warm-up frame of its own; an image is required.
            args = [self.binary, "render", *self.arguments, "-o", output + ".png", "--stats", output]
            if frames and "--frames" not in self.arguments:
                args += ["--frames", str(frames)]
        else:
            args = [self.binary, "bench", *self.arguments, "--json" if json_output else "--csv", output]
            if frames and "--frames" not in self.arguments:
                args += ["--frames", str(frames)]
            if warmup is not None and "--warmup" not in self.arguments:
                args += ["--warmup", str(warmup)]
        return args + extra


_JSON_SUPPORT = {}


def has_json(binary):
    """Whether `binary`'s bench has --json."""
    if binary not in _JSON_SUPPORT:
        help_text = subprocess.run([binary, "bench", "--help"], capture_output=True, text=True).stdout
        _JSON_SUPPORT[binary] = "--json" in help_text
    return _JSON_SUPPORT[binary]


def csv_document(path, table_text):
    """A --csv of a build without --json, in --json's shape (docs/cli.md documents both)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    # The table's first line: "SCENE on DEVICE, driver profile P" (or without the profile).
    first = table_text.splitlines()[0] if table_text else ""
    device = first.split(" on ", 1)[1].rsplit(", driver profile", 1)[0] if " on " in first else "unknown"
    results = []
    for r in rows:
        timing = r.get("pass_timing") or "wall"
        gpu = dict(p.split(":", 1) for p in filter(None, (r.get("pass_gpu_ms") or "").split(";")))
        passes = []
        for entry in filter(None, r["passes"].split(";")):
            name, wall, invocations = (entry.split(":") + ["", ""])[:3]
            wall_ms = float(wall) if wall else None
            gpu_ms = float(gpu[name]) if gpu.get(name) else None
            ms = wall_ms if timing == "wall" else gpu_ms
            passes.append({"name": name, "ms": ms, "clock": None if ms is None else ("wall" if timing == "wall" else "gpu"),
                           "wall_ms": wall_ms, "gpu_ms": gpu_ms,
                           "fragment_invocations": int(invocations) if invocations else None})
        statistic = lambda name: float(r[name]) if r.get(name) else None
        frame = {"median": statistic("frame_ms_median"), "p95": statistic("frame_ms_p95"),
                 "min": statistic("frame_ms_min"), "max": statistic("frame_ms_max")}
        work = {k: int(r[k]) for k in ("light_evaluations", "in_range_pairs", "transparent_light_evaluations")
                if r.get(k)}
        results.append({"technique": r["technique"], "lights": int(r["lights"]), "width": int(r["width"]),
                        "height": int(r["height"]), "frames": int(r["frames"]), "pass_timing": timing,
                        "frame_ms": frame, "frame_gpu_ms": {"median": statistic("frame_gpu_ms_median")},
                        "passes": passes, "counters": {}, "work": work or None})
    return {"device": device, "pass_timing": results[0]["pass_timing"] if results else "wall", "results": results}


def run_command(args, environment):
    """Runs one command; returns its peak resident memory in bytes, its seconds and its stdout. A
    failure ends the measurement with the command's own message."""
    env = dict(os.environ, **environment)
    start = time.monotonic()
    with tempfile.TemporaryFile("w+") as stdout:
        process = subprocess.Popen(args, env=env, stdout=stdout, stderr=subprocess.PIPE, text=True)
        with process.stderr:
            stderr = process.stderr.read()
        _, status, usage = os.wait4(process.pid, 0)
        stdout.seek(0)
        stdout_text = stdout.read()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        shown = " ".join(f"{k}={v}" for k, v in environment.items()) + " " + shlex.join(args)
        sys.exit(f"bench.py: '{shown.strip()}' failed with exit status {process.returncode}:\n{stderr.strip()}")
    return usage.ru_maxrss * 1024.0, time.monotonic() - start, stdout_text  # ru_maxrss: KiB on Linux


def render_rows(stats):
    """render --stats as one row of bench --json's shape."""
    timing = stats.get("pass_timing", "wall")
    passes = []
    for p in stats.get("passes", []):
        ms = p.get("wall_ms") if timing == "wall" else p.get("gpu_ms")
        passes.append(dict(p, ms=ms, clock=None if ms is None else ("wall" if timing == "wall" else "gpu")))
    work = {k: stats[k] for k in ("light_evaluations", "in_range_pairs", "transparent_light_evaluations") if k in stats}
    scalars = {k: v for k, v in stats.items() if isinstance(v, (int, float)) and not isinstance(v, bool)}
    return [{"technique": stats["technique"], "lights": stats["lights"], "width": stats["width"],
             "height": stats["height"], "pass_timing": timing, "frame_ms": stats["frame_ms"],
             "frame_gpu_ms": stats["frame_gpu_ms"], "passes": passes, "counters": scalars, "stats": scalars,
             "work": work or None}]


def run_case(case, frames, warmup, extra):
    """Runs `case` once; returns (the document's header, its rows)."""
    with tempfile.TemporaryDirectory() as scratch:
        output = os.path.join(scratch, "out.json")
        json_output = case.render or has_json(case.binary)
        rss, seconds, stdout = run_command(case.command(output, frames, warmup, extra, json_output), case.environment)
        if json_output:
            with open(output) as f:
                document = json.load(f)
        else:
            document = csv_document(output, stdout)
    rows = render_rows(document) if case.render else document["results"]
    for row in rows:
        row["peak_rss_bytes"] = rss
        row["process_s"] = seconds
    return document, rows


def ensure_binary():
    binary = os.environ.get("ML")
    if binary:
        return binary
    subprocess.run(["make", "-C", ROOT, "app"], check=True, stdout=subprocess.DEVNULL)
    return os.path.join(ROOT, "build", "manylights")


# --- columns ----------------------------------------------------------------------------------


class Sum:
    """Terms joined by ' + ' and ' - '."""

    def __init__(self, expression):
        parts = re.split(r"\s([+-])\s", " " + expression.strip() + " ")
        self.terms = [(1.0, parts[0].strip())]
        for sign, term in zip(parts[1::2], parts[2::2]):
            self.terms.append((1.0 if sign == "+" else -1.0, term.strip()))

    def value(self, row):
        """The sum, or None where the row has none of it."""
        total, found, passes_named, passes_found = 0.0, True, False, False
        for sign, term in self.terms:
            value = term_value(row, term)
            if value is _PASS_ABSENT:
                passes_named = True
                continue
            if isinstance(value, tuple):  # a pass, and whether it was timed
                passes_named, passes_found = True, True
                if value[0] is None:
                    found = False
                    continue
                value = value[0]
            if value is None:
                found = False
                continue
            total += sign * value
        if not found or (passes_named and not passes_found):
            return None
        return total


class Column:
    """A figure of a row: NAME=EXPRESSION, or an EXPRESSION that names itself."""

    def __init__(self, spec):
        name, separator, expression = spec.partition("=")
        if not separator:
            name, expression = spec, spec
        self.name = name.strip()
        numerator, _, denominator = expression.partition(" / ")
        self.numerator = Sum(numerator)
        self.denominator = Sum(denominator) if denominator.strip() else None
        self.is_ratio = self.denominator is not None

    def value(self, row):
        """The figure, or None where the row has none of it."""
        value = self.numerator.value(row)
        if self.denominator is None or value is None:
            return value
        divisor = self.denominator.value(row)
        return value / divisor if divisor else None

    def clocks(self, row):
        """The clocks the column's passes were timed on in `row` (none for a ratio)."""
        if self.is_ratio:
            return set()
        names = {p["name"]: p for p in row.get("passes", [])}
        found = set()
        for _, term in self.numerator.terms:
            for name, p in names.items():
                if fnmatch.fnmatchcase(name, term) and p.get("clock"):
                    found.add(p["clock"])
        return found


_PASS_ABSENT = object()


def term_value(row, term):
    if " * " in term:  # a product of figures: 'lights * pixels'
        product = 1.0
        for factor in term.split(" * "):
            value = term_value(row, factor.strip())
            if isinstance(value, tuple):  # a pass's time may be a factor too: 'lighting * 1000000'
                value = value[0]
            if not isinstance(value, float):
                return None
            product *= value
        return product
    if term == "frame":
        return row["frame_ms"]["median"]
    if term == "gpu frame":
        return row["frame_gpu_ms"]["median"]
    try:
        return float(term)  # a constant: 'gpu MiB=counter.gpu_memory_bytes / 1048576'
    except ValueError:
        pass
    if term == "peak rss":
        return row.get("peak_rss_bytes")
    if term == "process s":
        return row.get("process_s")
    if term == "lights":
        return float(row["lights"])
    if term == "pixels":
        return float(row["width"] * row["height"])
    if term.startswith("invocations."):
        counts = [p.get("fragment_invocations") for p in row.get("passes", [])
                  if fnmatch.fnmatchcase(p["name"], term[len("invocations."):])]
        return float(sum(counts)) if counts and None not in counts else None
    for prefix, key in (("counter.", "counters"), ("work.", "work"), ("stat.", "stats")):
        if term.startswith(prefix):
            # stat.: render --stats' numbers, or the bench row's own (warmup_frames).
            fields = row.get(key) or (row if key == "stats" else {})
            value = fields.get(term[len(prefix):])
            if isinstance(value, dict):
                value = None
            return None if value is None else float(value)
    matched = [p for p in row.get("passes", []) if fnmatch.fnmatchcase(p["name"], term)]
    if not matched:
        return _PASS_ABSENT
    times = [p.get("ms") for p in matched]
    return (None if any(t is None for t in times) else sum(times),)


# --- the report -------------------------------------------------------------------------------


def row_key(row):
    return (row["technique"], row["lights"], f"{row['width']}x{row['height']}")


def format_value(value, digits):
    if value is None:
        return "-"
    if abs(value) >= 1e5:
        return f"{value:,.0f}"
    return f"{value:.{digits}f}"


def median_or_none(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def spread(values, digits):
    values = [v for v in values if v is not None]
    if len(values) < 2 or min(values) == max(values):
        return ""
    return f" ({format_value(min(values), digits)}-{format_value(max(values), digits)})"


def passes_text(rows):
    """Every pass of the rows (one combination's rounds) with its median over them and its
    clock: 'geometry 3.1, lighting 389.4 (wall)'."""
    names, times, clocks = [], {}, set()
    for row in rows:
        for p in row.get("passes", []):
            if p["name"] not in times:
                names.append(p["name"])
            times.setdefault(p["name"], []).append(p.get("ms"))
            if p.get("clock"):
                clocks.add(p["clock"])
    text = ", ".join(f"{name} {format_value(median_or_none(times[name]), 1)}" for name in names)
    return text + (f" ({'/'.join(sorted(clocks))})" if clocks else " (no pass times)")


def table(rows, left):
    widths = [max(len(r[c]) for r in rows) for c in range(len(rows[0]))]
    lines = []
    for r in rows:
        cells = [r[c].ljust(widths[c]) if left[c] else r[c].rjust(widths[c]) for c in range(len(r))]
        lines.append("  ".join(cells).rstrip())
    return "\n".join(lines)


class Measurement:
    def __init__(self, cases, columns, rounds, frames=None, warmup=None, extra=(), digits=1, quiet_rounds=False,
                 all_passes=False):
        self.cases, self.columns, self.rounds = cases, columns, rounds
        self.frames, self.warmup, self.extra, self.digits = frames, warmup, list(extra), digits
        self.quiet_rounds, self.all_passes = quiet_rounds, all_passes
        # (case label, row key) -> a list of rows, one per round.
        self.results = {}
        self.order = []
        self.first_document = None

    def run(self, out=sys.stdout):
        for round_number in range(self.rounds):
            shift = round_number % len(self.cases)
            for case in self.cases[shift:] + self.cases[:shift]:
                document, rows = run_case(case, self.frames, self.warmup, self.extra)
                if self.first_document is None:
                    self.first_document = document
                    print(gl_line(document), file=out, flush=True)
                for row in rows:
                    key = (case.label, row_key(row))
                    if key not in self.results:
                        self.order.append(key)
                    self.results.setdefault(key, []).append(row)
                    if not self.quiet_rounds:
                        print(f"round {round_number + 1}: {self.round_line(case, row)}", file=out, flush=True)

    def digits_of(self, column):
        return 3 if column.is_ratio else self.digits

    def round_line(self, case, row):
        technique, lights, size = row_key(row)
        text = f"{case.label}: {technique} {lights:,} lights {size}: frame {format_value(row['frame_ms']['median'], self.digits)} ms"
        for column in self.columns:
            text += f", {column.name} {format_value(column.value(row), self.digits_of(column))}"
        if self.all_passes:
            text += "; " + passes_text([row])
        return text

    def column_title(self, column):
        clocks = set()
        for rows in self.results.values():
            for row in rows:
                clocks |= column.clocks(row)
        return column.name + (f" ({'/'.join(sorted(clocks))} ms)" if clocks else "")

    def figures(self, label, key):
        rows = self.results[(label, key)]
        frame = [r["frame_ms"]["median"] for r in rows]
        return [frame] + [[c.value(r) for r in rows] for c in self.columns]

    def summary(self):
        rounds = f"median of {self.rounds} rounds (min-max)" if self.rounds > 1 else "one round"
        header = ["case", "technique", "lights", "size", f"frame ms, {rounds}"]
        header += [self.column_title(c) for c in self.columns]
        rows = [header]
        if self.all_passes:
            header.append("passes (median ms, each on its clock)")
        for label, key in self.order:
            technique, lights, size = key
            line = [label, technique, f"{lights:,}", size]
            digits = [self.digits] + [self.digits_of(c) for c in self.columns]
            for values, d in zip(self.figures(label, key), digits):
                line.append(format_value(median_or_none(values), d) + spread(values, d))
            if self.all_passes:
                line.append(passes_text(self.results[(label, key)]))
            rows.append(line)
        return table(rows, [True, True, False, False] + [False] * (1 + len(self.columns)) + [True] * self.all_passes)

    def series(self):
        names = []
        for case in self.cases:
            if case.series not in names:
                names.append(case.series)
        return names

    def compare(self):
        """The first series' medians over the second's, row by row (the same point, technique,
        light count and size)."""
        names = self.series()
        if len(names) < 2:
            return "--compare needs two series of cases"
        first, second = names[0], names[1]
        by_series = {}
        for label, key in self.order:
            series, _, point = label.partition("/")
            by_series.setdefault(series, {})[(point, key)] = label
        rows = [["point", "technique", "lights", "size", "frame"] + [c.name for c in self.columns]]
        for (point, key), label in by_series.get(first, {}).items():
            other = by_series.get(second, {}).get((point, key))
            if other is None:
                continue
            line = [point or "-", key[0], f"{key[1]:,}", key[2]]
            for a, b in zip(self.figures(label, key), self.figures(other, key)):
                a, b = median_or_none(a), median_or_none(b)
                line.append(f"{a / b:.2f}" if a is not None and b else "-")
            rows.append(line)
        return f"{first} / {second}, the ratio of the medians:\n" + table(
            rows, [True, True, False, False] + [False] * (1 + len(self.columns)))

    def per_pair(self, column, pairs="light_evaluations"):
        """ns per pair: the change of `column` between the fewest and the most pairs (--count-work's
        `pairs`) of each series, technique and size, over the change of the pairs; and each
        against the first series' of the same technique and size."""
        groups = {}
        for label, key in self.order:
            series = label.partition("/")[0]
            groups.setdefault((series, key[0], key[2]), []).append((label, key))
        rows = [["series", "technique", "size", pairs.replace("_", " "), f"{column.name} ms", "ns per pair",
                 "/ the first series'"]]
        first = {}
        for (series, technique, size), members in groups.items():
            points = []
            for label, key in members:
                results = self.results[(label, key)]
                evaluations = median_or_none([(r.get("work") or {}).get(pairs) for r in results])
                ms = median_or_none([column.value(r) for r in results])
                if evaluations is not None and ms is not None:
                    points.append((evaluations, ms))
            if len(points) < 2:
                continue
            (ea, ma), (eb, mb) = min(points), max(points)
            per_pair = (mb - ma) * 1e6 / (eb - ea) if eb != ea else None
            reference = first.setdefault((technique, size), per_pair)
            rows.append([series, technique, size, f"{ea:,.0f} -> {eb:,.0f}", f"{ma:.1f} -> {mb:.1f}",
                         "-" if per_pair is None else f"{per_pair:.2f}",
                         f"{per_pair / reference:.2f}" if per_pair is not None and reference else "-"])
        return f"ns per (pixel, light) pair of {column.name}:\n" + table(
            rows, [True, True, True, False, False, False, False])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", action="append", metavar="'LABEL: ARGUMENTS'",
                        help="a command line to measure (repeat)")
    parser.add_argument("--binary", action="store_true",
                        help="print the binary to measure (ML, or build/manylights built) and stop: for scripts "
                             "that measure outside bench")
    parser.add_argument("--machine", action="store_true",
                        help="print the machine header (of ML's binary) and stop: for scripts that measure "
                             "outside bench")
    parser.add_argument("--rounds", type=int, default=int(os.environ.get("ROUNDS", 1)),
                        help="times every case runs, interleaved (default ROUNDS or 1)")
    parser.add_argument("--frames", type=int, help="timed frames per combination (--frames of bench and render)")
    parser.add_argument("--warmup", type=int, help="bench's warm-up frames (default bench's: auto)")
    parser.add_argument("--column", action="append", default=[], metavar="[NAME=]EXPRESSION",
                        help="a figure per row besides the frame (repeat)")
    parser.add_argument("--compare", action="store_true", help="the first series over the second, row by row")
    parser.add_argument("--per-pair", metavar="COLUMN", help="ns per light evaluation of this column")
    parser.add_argument("--pairs", default="light_evaluations", choices=["light_evaluations", "in_range_pairs"],
                        help="the --count-work count --per-pair divides by (default light_evaluations)")
    parser.add_argument("--passes", action="store_true", help="every pass of each row, with its clock")
    parser.add_argument("--digits", type=int, default=1, help="decimals of the times (default 1)")
    parser.add_argument("--quiet-rounds", action="store_true", help="no line per run, the summary only")
    args = parser.parse_args(argv)
    if args.binary:
        print(ensure_binary())
        return
    if args.machine:
        print(machine_header([ensure_binary()]), flush=True)
        return
    if not args.case:
        parser.error("at least one --case is needed")
    if args.rounds < 1:
        parser.error("--rounds must be at least 1")

    binary = ensure_binary()
    cases = [Case(spec, binary) for spec in args.case]
    columns = [Column(spec) for spec in args.column]
    per_pair = None
    if args.per_pair:
        per_pair = Column(args.per_pair)
        named = [c for c in columns if c.name == per_pair.name]
        if named:
            per_pair = named[0]
        else:
            columns.append(per_pair)
    extra = shlex.split(os.environ.get("BENCH_ARGS", ""))
    print(machine_header(sorted({c.binary for c in cases})), flush=True)
    measurement = Measurement(cases, columns, args.rounds, args.frames, args.warmup, extra, args.digits,
                              args.quiet_rounds, args.passes)
    measurement.run()
    print()
    print(measurement.summary())
    if args.compare:
        print()
        print(measurement.compare())
    if per_pair:
        print()
        print(measurement.per_pair(per_pair, args.pairs))
    print(f"load average at the end: {load_average()}")


if __name__ == "__main__":
    main()
