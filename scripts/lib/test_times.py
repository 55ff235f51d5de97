#!/usr/bin/env python3
"""The test suite's times (docs/testing.md, "The suite's time"), for scripts/measure-test-times.sh.

    test_times.py sum LOG [--top N]              the tests of one CTest log (LastTest.log): their
                                                 count, the sum of their times and the N slowest
    test_times.py compare BEFORE AFTER [--top N] two logs: both sums, and the tests whose times
                                                 changed most, before and after
    test_times.py interleave REGEX DIR... [--rounds R] [--jobs J]
                                                 runs the tests matching REGEX in each build folder
                                                 in turn (ctest -j J, 1 unless given), the order
                                                 rotated every round, and prints each run's wall
                                                 time and each test's times per folder
    test_times.py processes FILTER PROGRAM... [--rounds R] [--jobs J]
                                                 the GoogleTest programs' tests matching FILTER, one
                                                 process each (J at a time, 1 unless given), then
                                                 all in one process, each program in turn, every
                                                 round: each way's wall time
    test_times.py interleave-gtest FILTER PROGRAM... [--rounds R]
                                                 the same with GoogleTest programs (--gtest_filter),
                                                 e.g. a copy of the image_tests built before a change

Each prints the machine and its load first and last (scripts/lib/bench.py's header).
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "cmake"))
import write_test_groups  # noqa: E402  (the listing of a GoogleTest program's tests)


def read_log(path):
    """{test name: (seconds, passed)} from CTest's LastTest.log."""
    times = {}
    name = None
    seconds = None
    with open(path, errors="replace") as f:
        for line in f:
            match = re.match(r"^\d+/\d+ Test: (.+)$", line.rstrip("\n"))
            if match:
                name, seconds = match.group(1), None
                continue
            match = re.match(r"^Test time =\s*([\d.]+) sec", line)
            if match and name is not None:
                seconds = float(match.group(1))
                continue
            if name is not None and seconds is not None and line.startswith("Test "):
                times[name] = (seconds, line.startswith("Test Passed"))
                name = None
    return times


def header():
    return "\n".join(bench.machine_header([]).splitlines()[:2])


def print_sum(path, top):
    times = read_log(path)
    total = sum(s for s, _ in times.values())
    failed = sum(1 for _, passed in times.values() if not passed)
    print(f"{path}: {len(times)} tests ({failed} not passed), sum of their times {total:.0f} s")
    print(f"the {top} slowest:")
    for name, (seconds, _) in sorted(times.items(), key=lambda item: -item[1][0])[:top]:
        print(f"  {seconds:8.2f} s  {100 * seconds / total:5.1f} %  {name}")
    return total


def compare(before_path, after_path, top):
    before, after = read_log(before_path), read_log(after_path)
    total_before = sum(s for s, _ in before.values())
    total_after = sum(s for s, _ in after.values())
    print(f"before: {len(before)} tests, {total_before:.0f} s ({before_path})")
    print(f"after:  {len(after)} tests, {total_after:.0f} s ({after_path}): {total_after / total_before:.2f} of before")
    gone = sorted(set(before) - set(after))
    new = sorted(set(after) - set(before))
    if gone:
        print("only before: " + ", ".join(gone))
    if new:
        print("only after: " + ", ".join(new))
    changes = sorted((after[n][0] - before[n][0], n) for n in set(before) & set(after))
    print(f"the {top} tests whose time fell most (before -> after, s):")
    for change, name in changes[:top]:
        print(f"  {before[name][0]:8.2f} -> {after[name][0]:7.2f}  {name}")


def interleave(regex, folders, rounds, jobs=1):
    runs = {folder: {} for folder in folders}
    walls = {folder: [] for folder in folders}
    for round_number in range(rounds):
        shift = round_number % len(folders)
        for folder in folders[shift:] + folders[:shift]:
            start = time.monotonic()
            output = subprocess.run(["ctest", "--test-dir", folder, "-R", regex, "-j", str(jobs)],
                                    capture_output=True, text=True).stdout
            walls[folder].append(time.monotonic() - start)
            # A name may hold spaces (a group's "(part 1 of 3)", tests/cmake/write_test_groups.py).
            for match in re.finditer(r"Test\s+#\d+: (\S.*?) \.+\s*(\*\*\*)?(\w[\w ]*?)\s+([\d.]+) sec", output):
                runs[folder].setdefault(match.group(1), []).append((float(match.group(4)), match.group(3)))
            print(f"round {round_number + 1}: {folder}: {walls[folder][-1]:.1f} s (ctest -j {jobs}, "
                  f"{len(re.findall(r'Test +#', output))} tests), load average {bench.load_average()}", flush=True)
    print("ctest's wall time per round: " + " | ".join(
        folder + " " + ", ".join(f"{w:.1f}" for w in walls[folder]) for folder in folders))
    names = sorted({n for per_test in runs.values() for n in per_test})
    print("test: seconds per round in " + " | ".join(folders) + " (medians)")
    for name in names:
        cells = []
        for folder in folders:
            values = runs[folder].get(name, [])
            seconds = [s for s, _ in values]
            statuses = {status for _, status in values}
            shown = ", ".join(f"{s:.2f}" for s in seconds) or "-"
            if seconds:
                shown += f" ({statistics.median(seconds):.2f})"
            if statuses - {"Passed"}:
                shown += " " + "/".join(sorted(statuses - {"Passed"}))
            cells.append(shown)
        print(f"  {name}: " + " | ".join(cells))


def interleave_gtest(pattern, programs, rounds):
    runs = {program: {} for program in programs}
    for round_number in range(rounds):
        shift = round_number % len(programs)
        for program in programs[shift:] + programs[:shift]:
            output = subprocess.run([program, f"--gtest_filter={pattern}"], capture_output=True, text=True).stdout
            for match in re.finditer(r"^\[\s+(OK|FAILED)\s+\] (\S+) \((\d+) ms\)", output, re.MULTILINE):
                runs[program].setdefault(match.group(2), []).append((int(match.group(3)) / 1000.0, match.group(1)))
            print(f"round {round_number + 1}: {program} done, load average {bench.load_average()}", flush=True)
    names = sorted({n for per_test in runs.values() for n in per_test})
    print("test: seconds per round in " + " | ".join(programs) + " (medians)")
    totals = {program: 0.0 for program in programs}
    for name in names:
        cells = []
        for program in programs:
            values = runs[program].get(name, [])
            seconds = [s for s, _ in values]
            shown = ", ".join(f"{s:.2f}" for s in seconds) or "-"
            if seconds:
                shown += f" ({statistics.median(seconds):.2f})"
                totals[program] += statistics.median(seconds)
            if any(status != "OK" for _, status in values):
                shown += " FAILED"
            cells.append(shown)
        print(f"  {name}: " + " | ".join(cells))
    print("sum of the medians: " + " | ".join(f"{totals[p]:.1f} s" for p in programs))


def timed(commands, jobs):
    """Seconds to run `commands` (argument lists), `jobs` at a time; raises if one fails."""
    start = time.monotonic()
    pending, running = list(commands), []
    while pending or running:
        while pending and len(running) < jobs:
            running.append(subprocess.Popen(pending.pop(0), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        process = running.pop(0)
        if process.wait() != 0:
            raise SystemExit(f"test_times.py: {' '.join(process.args)} failed (exit {process.returncode})")
    return time.monotonic() - start


def processes(pattern, programs, rounds, jobs):
    """The tests matching `pattern` run one process each (`jobs` at a time) and all in one
    process, with each program in turn; the wall times per round."""
    walls = {(program, how): [] for program in programs for how in ("each", "one")}
    for round_number in range(rounds):
        shift = round_number % len(programs)
        for program in programs[shift:] + programs[:shift]:
            names = write_test_groups.list_tests(program, pattern, 60)
            walls[(program, "each")].append(timed([[program, f"--gtest_filter={name}"] for name in names], jobs))
            walls[(program, "one")].append(timed([[program, f"--gtest_filter={pattern}"]], 1))
            print(f"round {round_number + 1}: {program}: {len(names)} tests, one process each ({jobs} at a time) "
                  f"{walls[(program, 'each')][-1]:.1f} s, all in one {walls[(program, 'one')][-1]:.1f} s, "
                  f"load average {bench.load_average()}", flush=True)
    for program in programs:
        print(f"{program}: one process each " + ", ".join(f"{w:.1f}" for w in walls[(program, "each")]) +
              " s; all in one " + ", ".join(f"{w:.1f}" for w in walls[(program, "one")]) + " s")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    p = commands.add_parser("sum")
    p.add_argument("log")
    p.add_argument("--top", type=int, default=20)
    p = commands.add_parser("compare")
    p.add_argument("before")
    p.add_argument("after")
    p.add_argument("--top", type=int, default=20)
    p = commands.add_parser("interleave")
    p.add_argument("regex")
    p.add_argument("folders", nargs="+")
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--jobs", type=int, default=1)
    p = commands.add_parser("processes")
    p.add_argument("pattern")
    p.add_argument("programs", nargs="+")
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--jobs", type=int, default=1)
    p = commands.add_parser("interleave-gtest")
    p.add_argument("pattern")
    p.add_argument("programs", nargs="+")
    p.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    print(header(), flush=True)
    if args.command == "sum":
        print_sum(args.log, args.top)
    elif args.command == "compare":
        compare(args.before, args.after, args.top)
    elif args.command == "interleave":
        interleave(args.regex, args.folders, args.rounds, args.jobs)
    elif args.command == "processes":
        processes(args.pattern, args.programs, args.rounds, args.jobs)
    else:
        interleave_gtest(args.pattern, args.programs, args.rounds)
    print(f"load average at the end: {bench.load_average()}")


if __name__ == "__main__":
    main()
